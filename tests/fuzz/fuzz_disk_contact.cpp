// Fuzzer of the disk-polygon contact (rbsm::diskPolygonContact, pkg/rbsm/kernel/DiskContact.hpp, the
// geometry of a YADE Sphere against a Polygon2D block) against CGAL's exact distances.
//
// Run:  fuzz_disk_contact                 (default 100000 random pairs, seed 1; ctest fuzz.disk_contact)
//       RBSM_FUZZ_N=... RBSM_FUZZ_SEED=... RBSM_FUZZ_VERBOSE=1 as for fuzz_edge_contact.
// Every pair: a random convex CCW polygon (3-8 vertices, hull of random points, size 0.01 to 100, aspect up
// to 20) at a random pose, and a disk whose centre is anywhere from deep inside to two sizes away (a third inside), radius
// 0.01 to 1 size. Checks (tol = 1e-9 × (size + distance of the centre from the polygon)):
//  1. finite: every number finite, |n| = 1;
//  2. cgal_distance: the signed distance equals CGAL's exact distance from the centre to the polygon's
//     boundary (minimum of the exact point-segment squared distances), negative inside (exact
//     bounded_side);
//  3. cgal_closest: the closest point lies on the boundary (exact distance below tol), the centre is at
//     distance × n from it, and the contact point is the middle of the overlap, q − (δ/2) n;
//  4. rigid_motion: rotating and translating polygon and disk (translation up to 100 sizes) moves the
//     contact with them: same overlap, R n, moved contact point;
//  5. relabelling (the polygon's own symmetry): starting the vertex list at another vertex gives the same
//     contact. Centres inside within 1e-9 size of two edge lines (the medial axis, where the normal
//     jumps between the two edges) are skipped in 4 and 5 and counted as ties.
#include <pkg/rbsm/kernel/ConvexPolygon.hpp>
#include <pkg/rbsm/kernel/DiskContact.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/squared_distance_2.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

using rbsm::Real;
using rbsm::Vec2;
using K = CGAL::Exact_predicates_exact_constructions_kernel;

namespace {
std::mt19937_64             rng;
bool                        verbose = false;
std::map<std::string, long> counts, info;
Real                        uni(Real a, Real b) { return std::uniform_real_distribution<Real>(a, b)(rng); }
int                         uniInt(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }

struct Poly {
	std::vector<Vec2> v, n;
	explicit Poly(std::vector<Vec2> vertices)
	        : v(std::move(vertices))
	        , n(rbsm::edgeNormals(v))
	{
	}
	rbsm::PolygonView view() const { return rbsm::PolygonView { v.data(), n.data(), int(v.size()) }; }
};

std::vector<Vec2> randomPolygon(Real size)
{
	for (;;) {
		const int  n      = uniInt(3, 8);
		const Real aspect = std::exp(uni(0, std::log(20.0)));
		std::vector<K::Point_2> pts, hull;
		for (int i = 0; i < n + 2; ++i) pts.emplace_back(uni(-0.5, 0.5) * size, uni(-0.5, 0.5) * size / aspect);
		CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(hull)); // CCW
		std::vector<Vec2> h;
		for (const auto& p : hull) h.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
		if (h.size() < 3 || !rbsm::polygonProblem(h).empty()) continue;
		const auto mp = rbsm::massProperties(h);
		for (auto& v : h) v -= mp.centroid;
		if (!rbsm::polygonProblem(h).empty()) continue;
		return h;
	}
}

// Exact signed distance from p to the boundary of P (negative inside), rounded once at the end.
Real exactSignedDistance(const std::vector<Vec2>& P, const Vec2& p)
{
	const K::Point_2 q(p.x(), p.y());
	K::FT            best = -1;
	CGAL::Polygon_2<K> poly;
	for (size_t i = 0; i < P.size(); ++i) {
		const K::Point_2 a(P[i].x(), P[i].y()), b(P[(i + 1) % P.size()].x(), P[(i + 1) % P.size()].y());
		const K::FT      d = CGAL::squared_distance(q, K::Segment_2(a, b));
		if (best < 0 || d < best) best = d;
		poly.push_back(a);
	}
	const Real d = std::sqrt(CGAL::to_double(best));
	return poly.bounded_side(q) == CGAL::ON_BOUNDED_SIDE ? -d : d;
}

void violation(const char* what, const std::string& detail)
{
	if (verbose && counts[what] < 5) std::printf("VIOLATION %s: %s\n", what, detail.c_str());
	counts[what]++;
}

bool nearMedialAxis(const Poly& P, const Vec2& c, Real tol)
{
	Real best = -INFINITY, second = -INFINITY;
	for (size_t i = 0; i < P.v.size(); ++i) {
		const Real s = P.n[i].dot(c - P.v[i]);
		if (s > best) second = best, best = s;
		else if (s > second) second = s;
	}
	return best <= 0 && best - second < tol;
}
}

int main()
{
	const long n    = std::getenv("RBSM_FUZZ_N") ? std::atol(std::getenv("RBSM_FUZZ_N")) : 100000;
	const long seed = std::getenv("RBSM_FUZZ_SEED") ? std::atol(std::getenv("RBSM_FUZZ_SEED")) : 1;
	verbose         = std::getenv("RBSM_FUZZ_VERBOSE") != nullptr;
	rng.seed(uint64_t(seed));
	for (const char* k : { "finite", "cgal_distance", "cgal_closest", "rigid_motion", "relabelling" }) counts[k] = 0;
	const auto t0 = std::chrono::steady_clock::now();
	Real       worst = 0;
	for (long it = 0; it < n; ++it) {
		const Real size = std::pow(10.0, uni(-2, 2));
		const Real ang  = uni(-M_PI, M_PI);
		const Vec2 pos(uni(-10, 10) * size, uni(-10, 10) * size);
		const Poly P(rbsm::toWorld(randomPolygon(size), pos, ang));
		// a third of the centres inside (a random convex combination of the vertices), the rest anywhere
		Vec2 c = pos + Vec2(uni(-1.5, 1.5), uni(-1.5, 1.5)) * size;
		if (uniInt(0, 2) == 0) {
			Real wsum = 0;
			c         = Vec2::Zero();
			for (const auto& v : P.v) {
				const Real w = std::pow(uni(0, 1), 4);
				c += w * v, wsum += w;
			}
			c /= wsum;
		}
		const Real r = std::pow(10.0, uni(-2, 0)) * size;

		const rbsm::DiskContact d = rbsm::diskPolygonContact(P.view(), c, r);
		const Real tol            = 1e-9 * (size + std::abs(d.distance)) + 1e-12 * pos.norm();
		char       buf[300];
		if (!(std::isfinite(d.distance) && std::isfinite(d.overlap) && d.normal.allFinite() && d.point.allFinite() && d.closest.allFinite()
		      && std::abs(d.normal.norm() - 1) < 1e-12)) {
			violation("finite", "non-finite contact or non-unit normal");
			continue;
		}
		const Real exact = exactSignedDistance(P.v, c);
		worst            = std::max(worst, std::abs(d.distance - exact) / size);
		if (std::abs(d.distance - exact) > tol) {
			std::snprintf(buf, sizeof buf, "distance %.17g, exact %.17g (size %.3g)", d.distance, exact, size);
			violation("cgal_distance", buf);
		}
		if (std::abs(exactSignedDistance(P.v, d.closest)) > tol || (c - d.closest - d.distance * d.normal).norm() > tol
		    || (d.point - (d.closest - 0.5 * d.overlap * d.normal)).norm() > tol || std::abs(d.overlap - (r - d.distance)) > tol) {
			std::snprintf(buf, sizeof buf, "closest point off the boundary by %.3g, or contact point/overlap inconsistent", exactSignedDistance(P.v, d.closest));
			violation("cgal_closest", buf);
		}
		if (nearMedialAxis(P, c, 1e-9 * size)) {
			info["ties (medial axis, skipped in 4-5)"]++;
			continue;
		}
		const Real a2 = uni(-M_PI, M_PI);
		const Vec2 T(uni(-100, 100) * size, uni(-100, 100) * size);
		const Poly M(rbsm::toWorld(P.v, T, a2));
		const rbsm::DiskContact m    = rbsm::diskPolygonContact(M.view(), rbsm::localToWorld(c, T, a2), r);
		const Real              tolM = tol + 1e-12 * (T.norm() + pos.norm());
		if (std::abs(m.overlap - d.overlap) > tolM || (m.normal - rbsm::rotate(d.normal, a2)).norm() > 1e-9
		    || (m.point - rbsm::localToWorld(d.point, T, a2)).norm() > tolM) {
			std::snprintf(buf, sizeof buf, "moved: overlap %.17g vs %.17g", m.overlap, d.overlap);
			violation("rigid_motion", buf);
		}
		std::vector<Vec2> shifted(P.v.begin() + 1, P.v.end());
		shifted.push_back(P.v.front());
		const Poly              S(shifted);
		const rbsm::DiskContact s = rbsm::diskPolygonContact(S.view(), c, r);
		if (std::abs(s.overlap - d.overlap) > tol || (s.normal - d.normal).norm() > 1e-9 || (s.point - d.point).norm() > tol) {
			std::snprintf(buf, sizeof buf, "relabelled: overlap %.17g vs %.17g", s.overlap, d.overlap);
			violation("relabelling", buf);
		}
		info[d.distance < 0 ? "centre inside" : "centre outside"]++;
		if (d.overlap > 0) info["overlapping"]++;
	}
	const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	std::printf("fuzz_disk_contact: %ld pairs, seed %ld, %.1f s\n", n, seed, secs);
	for (const auto& kv : info) std::printf("  %-40s %ld\n", kv.first.c_str(), kv.second);
	std::printf("  worst |distance - exact| / size          %.3g\nviolations:\n", worst);
	long bad = 0;
	for (const auto& kv : counts) {
		std::printf("  %-40s %ld\n", kv.first.c_str(), kv.second);
		bad += kv.second;
	}
	std::printf("%s\n", bad ? "FAILED" : "OK");
	return bad ? 1 : 0;
}
