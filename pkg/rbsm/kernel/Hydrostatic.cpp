#include <pkg/rbsm/kernel/Hydrostatic.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rbsm {

Real phreaticHeight(const std::vector<Vec2>& line, Real x)
{
	if (x <= line.front().x()) return line.front().y();
	for (std::size_t i = 1; i < line.size(); ++i)
		if (x <= line[i].x()) return line[i - 1].y() + (line[i].y() - line[i - 1].y()) * (x - line[i - 1].x()) / (line[i].x() - line[i - 1].x());
	return line.back().y();
}

void checkWaterTable(const std::string& who, const std::vector<Vec2>& line, Real gammaW)
{
	if (!(std::isfinite(gammaW) && gammaW >= 0))
		throw std::invalid_argument(who + ".waterUnitWeight: must be a finite number >= 0 (got " + std::to_string(gammaW) + ")");
	for (std::size_t i = 0; i < line.size(); ++i)
		if (!(std::isfinite(line[i].x()) && std::isfinite(line[i].y())) || (i > 0 && !(line[i].x() > line[i - 1].x())))
			throw std::invalid_argument(who + ".phreatic: point " + std::to_string(i)
			                            + " is not finite or its x does not increase (a polyline of strictly increasing x)");
}

namespace {
	// The water on the straight piece a→b where the head h(x) − y is linear (no polyline vertex inside).
	void addPiece(const Vec2& a, const Vec2& b, const std::vector<Vec2>& line, Real gammaW, const Vec2& about, WaterLoad& out)
	{
		const Real ua = gammaW * (phreaticHeight(line, a.x()) - a.y()), ub = gammaW * (phreaticHeight(line, b.x()) - b.y());
		if (ua <= 0 && ub <= 0) return;
		Vec2 p = a, q = b;
		Real up = ua, uq = ub;
		if (ua < 0 || ub < 0) { // the water table crosses the piece: keep the wet part
			const Vec2 w = a + (b - a) * (ua / (ua - ub));
			if (ua < 0) p = w, up = 0;
			else q = w, uq = 0;
		}
		const Vec2 d = q - p;
		const Vec2 inward(-d.y(), d.x()); // −n·length (counter-clockwise: the outward normal is (d.y, −d.x)/|d|)
		const Real um = 0.5 * (up + uq);
		out.force += um * inward;
		// moment: ∫ u (r × inward) over the piece, r linear and u linear: Simpson is exact
		auto m = [&](const Vec2& r, Real u) { return u * cross2(r - about, inward); };
		out.moment += (m(p, up) + 4 * m(0.5 * (p + q), um) + m(q, uq)) / 6;
	}
}

WaterLoad hydrostaticLoad(const std::vector<Vec2>& polygon, const std::vector<Vec2>& line, Real gammaW, const Vec2& about)
{
	WaterLoad out;
	const std::size_t n = polygon.size();
	for (std::size_t i = 0; i < n; ++i) {
		const Vec2 &a = polygon[i], &b = polygon[(i + 1) % n];
		// cut the edge at the polyline's vertices between a.x and b.x, where the head changes slope
		std::vector<Real> cuts { 0, 1 };
		for (const Vec2& v : line)
			if ((v.x() - a.x()) * (v.x() - b.x()) < 0) cuts.push_back((v.x() - a.x()) / (b.x() - a.x()));
		std::sort(cuts.begin(), cuts.end());
		for (std::size_t k = 1; k < cuts.size(); ++k)
			addPiece(a + cuts[k - 1] * (b - a), a + cuts[k] * (b - a), line, gammaW, about, out);
	}
	return out;
}

} // namespace rbsm
