"""yade_rbsm.io.describe: the classes a save file needs and which the local YADE lacks, for every
save format YADE writes, run from a YADE without the plugin (the collaborator's case)."""
import glob
import gzip
import os
import subprocess
import sys

import pytest
from yaderun import run_ok

from yade_rbsm.io.describe import __file__ as DESCRIBE_FILE
from yade_rbsm.io.describe import RBSM_CLASSES, describe

YADE_LIB_DIR = "/usr/lib/x86_64-linux-gnu/yade-double"
FORMATS = ("xml", "xml.bz2", "xml.gz", "yade", "yade.gz", "yade.bz2", "bin")
# the plugin's classes in a scene of engines() (not the qt view's functors, nor the mixed scenes' ones)
ENGINES_RBSM_CLASSES = {"Polygon2D", "Bo1_Polygon2D_Aabb", "RbsmMat", "RbsmGeom", "RbsmPhys", "Ig2_Polygon2D_Polygon2D_RbsmGeom",
                        "Ip2_RbsmMat_RbsmMat_RbsmPhys", "Law2_RbsmGeom_RbsmPhys_MohrCoulomb", "RbsmTimeStepper", "RbsmPairCheck"}
# (engines()' collider also bounds YADE's own shapes, so that a block next to one is reported)
RBSM_SCENE_CLASSES = {"ForceResetter", "InsertionSortCollider", "InteractionLoop", "Aabb", "Bo1_Sphere_Aabb", "Bo1_Wall_Aabb",
                      "Bo1_Facet_Aabb", "Bo1_Box_Aabb"} | ENGINES_RBSM_CLASSES

SAVE = r"""
from yade_rbsm import polygon2d, engines
rock = RbsmMat(density=2000, label="rock")
O.materials.append(rock)
O.bodies.append(polygon2d([(-5, -1), (5, -1), (5, 0), (-5, 0)], rock, fixed=True))
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], rock))
O.engines = engines(gravity=(0, -9.81, 0))
O.run(5, True)
for ext in FORMATS:
    O.save("rbsm." + ext)
O.reset()   # a scene of YADE's own classes only
O.bodies.append([sphere((0, 0, 0), 1), sphere((0, 0, 2.1), 1)])
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]), NewtonIntegrator()]
O.save("spheres.yade.gz")
import yade.system
report(classes=sorted(yade.system.childClasses("Serializable")))
"""


@pytest.fixture(scope="module")
def saved(tmp_path_factory):
    d = tmp_path_factory.mktemp("saves")
    (r,) = run_ok(SAVE.replace("FORMATS", repr(FORMATS)), workdir=str(d))
    return d, set(r["classes"])


@pytest.fixture(scope="module")
def plain_prefix(tmp_path_factory):
    """A YADE prefix with Debian's libraries but no yade-rbsm plugin (even if one were installed)."""
    prefix = tmp_path_factory.mktemp("plain")
    lib = prefix / "lib/x86_64-linux-gnu/yade-double"
    lib.mkdir(parents=True)
    for f in glob.glob(YADE_LIB_DIR + "/lib*.so") + [YADE_LIB_DIR + "/py"]:
        if os.path.basename(f) != "libpkg_rbsm.so":
            os.symlink(f, lib / os.path.basename(f))
    return str(prefix)


def plain_yade(prefix, args, cwd):
    env = dict(os.environ, YADE_PREFIX=prefix, PYTHONDONTWRITEBYTECODE="1")
    return subprocess.run(["/usr/bin/yade", "-n", "-x"] + args, capture_output=True, text=True, env=env, cwd=cwd, timeout=300)


@pytest.mark.parametrize("ext", FORMATS)
def test_classes_of_every_format(saved, ext):
    d, _ = saved
    info = describe(str(d / ("rbsm." + ext)), known=set())
    assert info.format == ("xml" if ext.startswith("xml") else "binary")
    assert info.compression == {"gz": "gzip", "bz2": "bzip2"}.get(ext.rsplit(".", 1)[-1])
    assert set(info.classes) == RBSM_SCENE_CLASSES
    assert ENGINES_RBSM_CLASSES <= RBSM_CLASSES
    assert info.rbsm == sorted(ENGINES_RBSM_CLASSES)


def test_plugin_class_list_is_up_to_date(saved, plain_prefix, tmp_path):
    """RBSM_CLASSES (stand-alone module) = the classes the built plugin adds to YADE."""
    _, with_plugin = saved
    p = plain_yade(plain_prefix, [DESCRIBE_FILE,
                                  "--list-local"], str(tmp_path))
    plain = set(p.stdout.split("YADE-CLASSES ")[1].split()) if "YADE-CLASSES " in p.stdout else None
    assert plain is not None, p.stdout + p.stderr
    assert with_plugin - plain == set(RBSM_CLASSES)


def test_plain_yade_cannot_load_and_describe_says_why(saved, plain_prefix):
    """A YADE without the plugin fails to load the scene without naming a class; the describe script,
    run by that YADE, names the ten missing classes and exits 1; a scene of YADE's own classes is fine."""
    d, _ = saved
    (d / "load.py").write_text("O.load('rbsm.yade.gz')\n")
    p = plain_yade(plain_prefix, ["load.py"], str(d))
    assert p.returncode != 0 and "unregistered class" in p.stdout + p.stderr
    script = DESCRIBE_FILE
    p = plain_yade(plain_prefix, [script, "rbsm.yade.gz"], str(d))
    assert p.returncode == 1, p.stdout + p.stderr
    assert "the local YADE lacks 10 of them" in p.stdout
    assert ", ".join(sorted(ENGINES_RBSM_CLASSES)) in p.stdout
    assert "install its Debian package" in p.stdout
    p = plain_yade(plain_prefix, [script, "spheres.yade.gz"], str(d))
    assert p.returncode == 0 and "the local YADE has all of them" in p.stdout, p.stdout + p.stderr


def test_plain_python_asks_yade(saved, plain_prefix, tmp_path):
    """From plain python3 the script runs `yade` ($YADE) once for its class list."""
    d, _ = saved
    wrapper = tmp_path / "yade"
    wrapper.write_text("#!/bin/sh\nYADE_PREFIX=%s exec /usr/bin/yade \"$@\"\n" % plain_prefix)
    wrapper.chmod(0o755)
    script = DESCRIBE_FILE
    p = subprocess.run([sys.executable, script, "rbsm.xml.bz2"], capture_output=True, text=True, cwd=str(d),
                       env=dict(os.environ, YADE=str(wrapper)), timeout=300)
    assert p.returncode == 1 and "the local YADE lacks 10 of them" in p.stdout, p.stdout + p.stderr


def test_bad_files(tmp_path):
    (tmp_path / "notes.txt").write_text("not a scene\n")
    with gzip.open(tmp_path / "cut.yade.gz", "wb") as f:
        f.write(b"\x16" + b"\0" * 7 + b"serialization::archive" + b"\0" * 100)
    raw = (tmp_path / "cut.yade.gz").read_bytes()
    (tmp_path / "cut.yade.gz").write_bytes(raw[:len(raw) // 2])
    for name, message in (("notes.txt", "not a YADE save file"), ("cut.yade.gz", "cannot read it as a YADE save file"),
                          ("absent.xml", "no such file")):
        with pytest.raises(ValueError, match="^%s: %s" % (str(tmp_path / name).replace(".", r"\."), message)):
            describe(str(tmp_path / name), known=set())
