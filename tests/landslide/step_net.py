"""A step-path joint network and its rigid-block limit equilibrium (plain Python, no YADE; written in a
new user's trial of rock slopes, session 13). Bedding dips `dip` out of the face in columns between
vertical cross joints every `w` m, `v` m apart vertically, offset by v/2 in alternate columns. A step path
starts where a bedding line daylights in the face, runs up along it and, at each cross joint, steps up to
a bedding line of the next column or ends up the cross joint (a tension crack). Its FS is that of a rigid
block translating along the bedding direction, the risers open:
    FS = (c Lb + W cos(dip) tan(phi)) / (W sin(dip)),  Lb the length along the bedding."""
import math

def interp(surf, x):
    for (xa, ya), (xb, yb) in zip(surf[:-1], surf[1:]):
        if xa <= x <= xb:
            return ya + (yb - ya) * (x - xa) / (xb - xa)
    raise ValueError(x)

def face_cross(surf, y0, m, xa, xb):
    """first x in [xa, xb] where line y = y0 + m (x - xa) meets the ground from below going right->left...
    returns x where ground(x) == line, scanning segments"""
    out = []
    for (sa, ya), (sb, yb) in zip(surf[:-1], surf[1:]):
        lo, hi = max(sa, xa), min(sb, xb)
        if hi <= lo:
            continue
        f = lambda x: interp(surf, x) - (y0 + m * (x - xa))
        fa, fb = f(lo), f(hi)
        if fa == fb:
            continue
        if (fa <= 0 <= fb) or (fb <= 0 <= fa):
            out.append(lo - fa * (hi - lo) / (fb - fa))
    return out

class Net:
    def __init__(self, surf, w, v, dip, x0=None, xn=None, base=0.0, ymin_line=None):
        self.surf, self.w, self.v, self.m = surf, w, v, math.tan(math.radians(dip))
        self.dip = math.radians(dip)
        self.x0 = surf[0][0] if x0 is None else x0
        self.xn = surf[-1][0] if xn is None else xn
        self.base = base
        self.xs = []
        x = self.x0 + w
        while x < self.xn - 1e-9:
            self.xs.append(x); x += w
        self.cols = [self.x0] + self.xs + [self.xn]
        self.ytop = max(y for _, y in surf)

    def lines(self, i):
        """bedding lines of column i: list of y at the column's left edge"""
        xa, xb = self.cols[i], self.cols[i + 1]
        off = 0.5 * self.v if i % 2 else 0.0
        ys = []
        k = -int((self.m * (xb - xa) + self.ytop) / self.v) - 2
        while True:
            y = self.base + off + k * self.v
            if y > self.ytop + 1:
                break
            if y + self.m * (xb - xa) > self.base and y < self.ytop:
                ys.append(y)
            k += 1
        return ys

    def polylines(self):
        """joint polylines: cross joints (vertical, base to ground) and bedding segments (clipped to
        the region y in (base, ground))"""
        out = []
        for x in self.xs:
            out.append([(x, self.base - 0.0), (x, interp(self.surf, x))])
        for i in range(len(self.cols) - 1):
            xa, xb = self.cols[i], self.cols[i + 1]
            for y in self.lines(i):
                # clip the segment to base <= y <= ground
                n = 200
                pts = [(xa + (xb - xa) * t / n, y + self.m * (xb - xa) * t / n) for t in range(n + 1)]
                inside = [self.base < p[1] < interp(self.surf, p[0]) for p in pts]
                if not any(inside):
                    continue
                # exact ends: base crossing and ground crossing
                xl, xr = xa, xb
                if y < self.base:
                    xl = xa + (self.base - y) / self.m
                gx = face_cross(self.surf, y, self.m, xa, xb)
                # ground above line at xl? keep the part under the ground
                segs = sorted(set([xl, xr] + [g for g in gx if xl < g < xr]))
                for a, b in zip(segs[:-1], segs[1:]):
                    xm = 0.5 * (a + b)
                    if y + self.m * (xm - xa) < interp(self.surf, xm):
                        out.append([(a, y + self.m * (a - xa)), (b, y + self.m * (b - xa))])
        return out

    def paths(self, max_paths=200000):
        """step paths: start where a bedding line daylights in the face (ground above to the right),
        go right along it; at each cross joint step up to any bedding line of the next column below
        the ground, or end by going up the cross joint to the ground (tension crack), or end where
        the bedding meets the ground again."""
        res = []
        for i in range(len(self.cols) - 1):
            xa, xb = self.cols[i], self.cols[i + 1]
            for y in self.lines(i):
                for g in face_cross(self.surf, y, self.m, xa, xb):
                    # daylight: ground below the line just left, above just right
                    e = 1e-6
                    if g - e > xa and interp(self.surf, g - e) < y + self.m * (g - e - xa) and g + e < xb and \
                            interp(self.surf, g + e) > y + self.m * (g + e - xa):
                        self._walk(i, y, [(g, y + self.m * (g - xa))], res)
        return res

    def _walk(self, i, y, pts, res):
        xa, xb = self.cols[i], self.cols[i + 1]
        x0 = pts[-1][0]
        # does the line reach the ground again inside the column?
        gx = [g for g in face_cross(self.surf, y, self.m, xa, xb) if g > x0 + 1e-6]
        if gx:
            res.append(pts + [(gx[0], y + self.m * (gx[0] - xa))])
            return
        yend = y + self.m * (xb - xa)
        p = pts + [(xb, yend)]
        if i + 1 >= len(self.cols) - 1:
            return  # reaches the right wall
        gy = interp(self.surf, xb)
        res.append(p + [(xb, gy)])  # tension crack up the cross joint
        for y2 in self.lines(i + 1):
            if yend < y2 < gy:
                self._walk(i + 1, y2, p + [(xb, y2)], res)


def area(poly):
    return 0.5 * sum(poly[k - 1][0] * poly[k][1] - poly[k][0] * poly[k - 1][1] for k in range(len(poly)))


def path_fs(net, path, c, phi, gamma):
    """translational rigid block along the bedding direction; risers open. Returns (fs, W, Lb, area)"""
    xs0, xs1 = path[0][0], path[-1][0]
    top = [p for p in net.surf if xs0 < p[0] < xs1]
    poly = list(path) + list(reversed(top))  # path left->right, then ground right->left
    A = area(poly)
    A = abs(A)
    W = gamma * A
    Lb = 0.0
    for a, b in zip(path[:-1], path[1:]):
        if abs(b[0] - a[0]) > 1e-9:
            Lb += math.hypot(b[0] - a[0], b[1] - a[1])
    fs = (c * Lb + W * math.cos(net.dip) * math.tan(phi)) / (W * math.sin(net.dip))
    return fs, W, Lb, A


def best(net, c, phi, gamma, k=5):
    ps = net.paths()
    rows = sorted((path_fs(net, p, c, phi, gamma) + (p,) for p in ps), key=lambda r: r[0])
    return rows[:k], len(ps)
