"""DXF import of closed polylines as blocks (yade_rbsm.io.import_dxf), from a drawing the test makes
with ezdxf; layers mapped to materials; clockwise outlines reversed; clear errors for the rest; and
export_dxf -> import_dxf gives the same blocks."""
import ezdxf
import pytest
from yaderun import run_ok

SQUARE = [(0, 0), (1, 0), (1, 1), (0, 1)]


def drawing(path):
    """Base (layer BASE, fixed), a CCW block, a CW block (reversed on import), a POLYLINE block, one
    closed by repeating its first vertex with a doubled vertex, and a LINE and a TEXT (skipped)."""
    doc = ezdxf.new("R2010")
    msp = doc.modelspace()
    for layer in ("BASE", "Rock", "Soil"):
        doc.layers.add(layer)
    msp.add_lwpolyline([(-5, -1), (5, -1), (5, 0), (-5, 0)], close=True, dxfattribs={"layer": "BASE"})
    msp.add_lwpolyline(SQUARE, close=True, dxfattribs={"layer": "Rock"})
    msp.add_lwpolyline([(2, 0), (2, 2), (3, 2), (3, 0)], close=True, dxfattribs={"layer": "Soil"})  # clockwise
    msp.add_polyline2d([(4, 0), (4.5, 0), (4.25, 0.5)], close=True, dxfattribs={"layer": "Soil"})
    msp.add_lwpolyline([(-2, 0), (-1, 0), (-1, 0), (-1.5, 1), (-2, 0)], dxfattribs={"layer": "rock"})
    msp.add_line((0, 5), (1, 5))
    msp.add_text("joint set A")
    doc.saveas(path)


IMPORT = r"""
import warnings
import yade_rbsm.io as io
rock = RbsmMat(label="rock", density=2500)
soil = RbsmMat(label="soil", density=1800)
O.materials.append([rock, soil])
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    bs = io.import_dxf("drawing.dxf", {"BASE": rock, "Rock": "rock", "Soil": soil}, fixed_layers=["base"])
O.bodies.append(bs)
report(n=len(bs), mats=[b.material.label for b in bs], fixed=[b.state.blockedDOFs for b in bs],
       areas=[b.shape.area for b in bs], pos=[list(b.state.pos)[:2] for b in bs],
       world=[[list(v) for v in b.shape.worldVertices(b.state.pos, b.state.ori)] for b in bs],
       warnings=[str(x.message) for x in w])
"""


def test_import_maps_layers_and_reverses_clockwise(tmp_path):
    drawing(str(tmp_path / "drawing.dxf"))
    (r,) = run_ok(IMPORT, workdir=str(tmp_path))
    assert r["n"] == 5
    assert r["mats"] == ["rock", "rock", "soil", "soil", "rock"]  # layer names match case-insensitively
    assert r["fixed"] == ["xyzXYZ", "zXY", "zXY", "zXY", "zXY"]
    assert r["areas"] == pytest.approx([10, 1, 2, 0.125, 0.5])
    assert r["pos"][2] == pytest.approx([2.5, 1])
    # the clockwise rectangle, reversed: counter-clockwise from its last drawn vertex
    assert sum(r["world"][2], []) == pytest.approx([3, 0, 3, 2, 2, 2, 2, 0])
    assert r["warnings"] == ["import_dxf: drawing.dxf: skipped 1 LINE, 1 TEXT (only LWPOLYLINE and POLYLINE make blocks)"]


BAD = {
    "open": (lambda m: m.add_lwpolyline(SQUARE, dxfattribs={"layer": "Rock"}), "open polyline"),
    "bow-tie": (lambda m: m.add_lwpolyline([(0, 0), (1, 1), (1, 0), (0, 1)], close=True, dxfattribs={"layer": "Rock"}),
                "self-intersecting polyline: edge 0 (0, 0)-(1, 1) meets edge 2 (1, 0)-(0, 1)"),
    "touching": (lambda m: m.add_lwpolyline([(0, 0), (2, 0), (2, 2), (1, 0), (0, 2)], close=True, dxfattribs={"layer": "Rock"}),
                 "self-intersecting polyline"),
    "non-convex": (lambda m: m.add_lwpolyline([(0, 0), (2, 0), (2, 2), (1, 1), (0, 2)], close=True, dxfattribs={"layer": "Rock"}),
                   "polygon2d([(0, 0), (2, 0), (2, 2), (1, 1), ... 5 vertices]): "),
    "arc": (lambda m: m.add_lwpolyline([(0, 0, 0.5), (1, 0, 0), (1, 1, 0)], format="xyb", close=True, dxfattribs={"layer": "Rock"}),
            "arc segment (bulge)"),
    "layer": (lambda m: m.add_lwpolyline(SQUARE, close=True, dxfattribs={"layer": "Clay"}),
              "layer 'Clay' has no material (materials= maps: 'Rock')"),
    "two points": (lambda m: m.add_lwpolyline([(0, 0), (1, 0), (0, 0)], close=True, dxfattribs={"layer": "Rock"}),
                   "fewer than 3 distinct vertices"),
}


def test_bad_polylines_are_refused_by_name(tmp_path):
    for name, (add, _) in BAD.items():
        doc = ezdxf.new("R2010")
        add(doc.modelspace())
        doc.saveas(str(tmp_path / ("%s.dxf" % name)))
    (tmp_path / "broken.dxf").write_text("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n")
    script = r"""
import yade_rbsm.io as io
errors = {}
for name in NAMES + ["broken", "missing"]:
    try:
        io.import_dxf(name + ".dxf", {"Rock": RbsmMat(density=2000)})
    except ValueError as e:
        errors[name] = str(e)
report(errors=errors)
""".replace("NAMES", repr(list(BAD)))
    (r,) = run_ok(script, workdir=str(tmp_path))
    errors = r["errors"]
    for name, (_, message) in BAD.items():
        assert name in errors, name
        entity, problem = errors[name].split(": ", 2)[:2], errors[name].split(": ", 2)[2]
        assert entity[0] == name + ".dxf" and entity[1].startswith("LWPOLYLINE #"), errors[name]
        assert " on layer " in entity[1]
        assert problem.startswith(message), (name, errors[name])
    assert errors["broken"].startswith("broken.dxf: ")
    assert errors["missing"].startswith("missing.dxf: cannot read the file")


def test_export_then_import_gives_the_same_blocks(tmp_path):
    script = r"""
import math
import yade_rbsm.io as io
from yade_rbsm import polygon2d
rock = RbsmMat(label="rock", density=2500)
O.materials.append(rock)
O.bodies.append(polygon2d([(-5, -1), (5, -1), (5, 0), (-5, 0)], rock, fixed=True))
O.bodies.append(polygon2d([(3 + math.cos(a), 2 + math.sin(a)) for a in [0.1 + 2 * math.pi * k / 6 for k in range(6)]], rock))
O.bodies[1].state.ori = Quaternion((0, 0, 1), 0.4)   # rotated: the world vertices differ from the drawn ones
def world():
    return [[list(v) for v in b.shape.worldVertices(b.state.pos, b.state.ori)] for b in O.bodies]
before = world()
assert io.export_dxf("out.dxf") == 2
O.bodies.clear()
O.bodies.append(io.import_dxf("out.dxf", {"rock": rock, "rock_fixed": rock}, fixed_layers=["rock_fixed"]))
report(before=before, after=world(), fixed=[b.state.blockedDOFs for b in O.bodies])
"""
    (r,) = run_ok(script, workdir=str(tmp_path))
    assert r["fixed"] == ["xyzXYZ", "zXY"]
    for b0, b1 in zip(r["before"], r["after"]):
        assert sum(b1, []) == pytest.approx(sum(b0, []), rel=1e-14, abs=1e-14)


UNITS = r"""
import yade_rbsm.io as io
rock = RbsmMat(label="rock", density=2500)
O.materials.append(rock)
out = {}
for f, kw in (("mm.dxf", {}), ("unitless.dxf", {}), ("unitless.dxf", {"units": "mm"}), ("ft.dxf", {})):
    bs = io.import_dxf(f, rock, **kw)
    out[f + str(kw)] = [b.shape.area for b in bs] + [b.state.mass for b in bs]
errors = {}
for f, kw in (("parsecs.dxf", {}), ("mm.dxf", {"units": "furlong"})):
    try:
        io.import_dxf(f, rock, **kw)
    except ValueError as e:
        errors[f + str(kw)] = str(e)
report(out=out, errors=errors)
"""


def _square_drawing(path, insunits, side):
    doc = ezdxf.new("R2010")
    if insunits is not None:
        doc.header["$INSUNITS"] = insunits
    doc.modelspace().add_lwpolyline([(0, 0), (side, 0), (side, side), (0, side)], close=True)
    doc.saveas(path)


def test_drawing_units_are_honoured(tmp_path):
    """Issue 36: a drawing in millimetres ($INSUNITS = 4) was read as metres: area x 1e6, mass 1.2e9 kg, no
    warning. Now $INSUNITS scales to metres (or units= says it); a unit that is no length is refused."""
    _square_drawing(str(tmp_path / "mm.dxf"), 4, 1000.0)  # a 1 m square drawn in mm
    _square_drawing(str(tmp_path / "unitless.dxf"), 0, 1000.0)
    _square_drawing(str(tmp_path / "ft.dxf"), 2, 1.0)
    _square_drawing(str(tmp_path / "parsecs.dxf"), 19, 1.0)  # 19: parsecs, no unit for a slope
    (r,) = run_ok(UNITS, workdir=str(tmp_path))
    assert r["out"]["mm.dxf{}"] == pytest.approx([1.0, 2500.0])
    assert r["out"]["unitless.dxf{}"] == pytest.approx([1e6, 2.5e9])  # unitless: metres, as before
    assert r["out"]["unitless.dxf{'units': 'mm'}"] == pytest.approx([1.0, 2500.0])
    assert r["out"]["ft.dxf{}"] == pytest.approx([0.3048 ** 2, 2500 * 0.3048 ** 2])
    assert "$INSUNITS = 19" in r["errors"]["parsecs.dxf{}"] and "units=" in r["errors"]["parsecs.dxf{}"]
    assert "furlong" in r["errors"]["mm.dxf{'units': 'furlong'}"]


def test_thickness_survives_export_and_import(tmp_path):
    """Issue 36: DXF export -> import turned a thickness of 0.5 m into 1.0 (the mass doubled) without a word.
    export_dxf writes each block's thickness (the entity's DXF thickness) and $INSUNITS = metres."""
    script = r"""
import yade_rbsm.io as io
from yade_rbsm import polygon2d
rock = RbsmMat(label="rock", density=2500)
O.materials.append(rock)
O.bodies.append(polygon2d([(0, 0), (2, 0), (2, 1), (0, 1)], rock, thickness=0.5))
O.bodies.append(polygon2d([(3, 0), (4, 0), (4, 1), (3, 1)], rock, thickness=2.0))
before = [(b.shape.thickness, b.state.mass) for b in O.bodies]
io.export_dxf("out.dxf")
O.bodies.clear()
O.bodies.append(io.import_dxf("out.dxf", rock))
after = [(b.shape.thickness, b.state.mass) for b in O.bodies]
import ezdxf
report(before=before, after=after, insunits=ezdxf.readfile("out.dxf").header.get("$INSUNITS"))
"""
    (r,) = run_ok(script, workdir=str(tmp_path))
    assert sum(r["after"], []) == pytest.approx(sum(r["before"], [])) and r["insunits"] == 6


UNITLESS = r"""
import warnings
import yade_rbsm.io as io
rock = RbsmMat(label="rock", density=2500)
O.materials.append(rock)
said = {}
for f, kw in (("wall_mm.dxf", {}), ("wall_mm.dxf", {"units": "mm"}), ("unitless.dxf", {})):
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        bs = io.import_dxf(f, rock, **kw)
    said[f + str(kw)] = [str(w.message) for w in seen if "no units" in str(w.message)]
report(said=said)
"""


def test_a_unitless_drawing_kilometres_across_is_named(tmp_path):
    """A 10 m block drawn in millimetres and saved without units is read in metres (as documented), 10 km across;
    import_dxf says so and names units='mm' (as read_slope_dxf does; it said nothing before). With units='mm' no
    warning; a drawing 1 km across (the test above's, a 1 m square in mm) is below the 5 km that is named."""
    _square_drawing(str(tmp_path / "wall_mm.dxf"), 0, 10000.0)
    _square_drawing(str(tmp_path / "unitless.dxf"), 0, 1000.0)
    (r,) = run_ok(UNITLESS, workdir=str(tmp_path))
    (message,) = r["said"]["wall_mm.dxf{}"]
    assert "import_dxf" in message and "wall_mm.dxf" in message and "units='mm'" in message, message
    assert r["said"]["wall_mm.dxf{'units': 'mm'}"] == [] and r["said"]["unitless.dxf{}"] == []
