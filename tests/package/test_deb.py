"""The Debian package yade-rbsm_*.deb: built by cpack from this build, its metadata and contents read
with dpkg-deb, compared with what `cmake --install` installs, and run by Debian's yade from a
`dpkg -x` extraction (an overlay prefix like the launcher's; nothing is installed into the system).
"""
import glob
import os
import subprocess
import tempfile

import pytest

SRC = os.path.abspath(os.environ.get("RBSM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")))
BUILD_DIR = os.path.abspath(os.environ.get("RBSM_BUILD_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "build")))
YADE_LIB_DIR = "/usr/lib/x86_64-linux-gnu/yade-double"
PLUGIN = "./usr/lib/x86_64-linux-gnu/yade-double/libpkg_rbsm.so"
DIST = "./usr/lib/python3/dist-packages"


def run(cmd, **kw):
    p = subprocess.run(cmd, capture_output=True, text=True, **kw)
    assert p.returncode == 0, "%s exited with %d\n%s\n%s" % (" ".join(cmd), p.returncode, p.stdout[-4000:], p.stderr[-4000:])
    return p.stdout


@pytest.fixture(scope="module")
def deb(tmp_path_factory):
    if not os.path.isfile(os.path.join(BUILD_DIR, "docs", "html", "index.html")):  # the package carries the manual
        run(["bash", os.path.join(SRC, "scripts", "build_docs.sh")], env=dict(os.environ, BUILD_DIR=BUILD_DIR), timeout=600)
    config = os.path.join(BUILD_DIR, "CPackConfig.cmake")
    assert os.path.isfile(config), "no %s: the build does not configure a package (include(Package))" % config
    out = tmp_path_factory.mktemp("deb")
    run(["cpack", "--config", config, "-B", str(out)])
    debs = glob.glob(str(out / "yade-rbsm_*.deb"))
    assert len(debs) == 1, "cpack wrote %r" % os.listdir(out)
    return debs[0]


def files_of(deb):
    """Regular files and symlinks in the package, as ./usr/... paths."""
    lines = run(["dpkg-deb", "-c", deb]).splitlines()
    return sorted(l.split()[5] for l in lines if l[0] in "-l")


def field(deb, name):
    return run(["dpkg-deb", "-f", deb, name]).strip()


def test_file_name_and_metadata(deb):
    assert os.path.basename(deb) == "yade-rbsm_%s_amd64.deb" % field(deb, "Version")
    assert field(deb, "Package") == "yade-rbsm"
    assert field(deb, "Architecture") == "amd64"
    assert field(deb, "Maintainer")
    assert "RBSM" in field(deb, "Description")
    depends = [d.strip() for d in field(deb, "Depends").split(",")]
    # pinned to the YADE binary whose layout yade-interface/ declares
    for d in ("yade (>= 2023.02a)", "yade (<< 2023.02b)", "libyade (>= 2023.02a)", "libyade (<< 2023.02b)"):
        assert d in depends, depends
    # the runtime libraries, found by dpkg-shlibdeps from the plugin's and the module's NEEDED entries
    for lib in ("libboost-python1.74.0", "libboost-serialization1.74.0", "libpython3.11", "libstdc++6", "libc6"):
        assert any(d.startswith(lib) for d in depends), (lib, depends)
    recommends = [r.strip() for r in field(deb, "Recommends").split(",")]
    for r in ("python3-ezdxf", "python3-vtk9", "python3-mpi4py", "openmpi-bin"):  # DXF, VTK, distributed runs
        assert r in recommends, recommends


def test_contents(deb):
    files = files_of(deb)
    for f in (PLUGIN, DIST + "/yade_rbsm_tessellation.so", DIST + "/yade_rbsm/__init__.py",
              DIST + "/yade_rbsm/blocks.py", DIST + "/yade_rbsm/mpi.py", DIST + "/yade_rbsm/io/__init__.py",
              "./usr/share/doc/yade-rbsm/copyright", "./usr/share/doc/yade-rbsm/README.md",
              "./usr/share/doc/yade-rbsm/html/index.html", "./usr/share/doc/yade-rbsm/html/reference/classes.html",
              "./usr/share/doc/yade-rbsm/html/tutorials/jointed_slope.html",
              "./usr/share/doc/yade-rbsm/examples/first_scene.py", "./usr/share/doc/yade-rbsm/examples/landslide_slope.py"):
        assert f in files, (f, files)
    assert not [f for f in files if "__pycache__" in f or f.endswith(".pyc")], files
    # nothing outside YADE's plugin directory, Python's dist-packages and the package's doc
    allowed = ("./usr/lib/x86_64-linux-gnu/yade-double/", DIST + "/", "./usr/share/doc/yade-rbsm/")
    assert all(f.startswith(allowed) for f in files), [f for f in files if not f.startswith(allowed)]
    # stripped: debug info stays out of the package
    root = tempfile.mkdtemp(prefix="yade-rbsm-deb-")
    run(["dpkg-deb", "-x", deb, root])
    sections = run(["readelf", "-SW", os.path.join(root, PLUGIN)])
    assert ".debug_info" not in sections


def test_maintainer_scripts(deb):
    ctl = tempfile.mkdtemp(prefix="yade-rbsm-ctl-")
    run(["dpkg-deb", "-e", deb, ctl])
    for name, tool in (("postinst", "py3compile -p yade-rbsm"), ("prerm", "py3clean -p yade-rbsm")):
        path = os.path.join(ctl, name)
        assert os.access(path, os.X_OK), name
        assert tool in open(path).read()
    run(["sh", "-n", os.path.join(ctl, "postinst")])


def test_same_files_as_cmake_install(deb):
    dest = tempfile.mkdtemp(prefix="yade-rbsm-install-")
    run(["cmake", "--install", BUILD_DIR], env=dict(os.environ, DESTDIR=dest))
    installed = sorted("./" + os.path.relpath(os.path.join(d, f), dest)
                       for d, _, fs in os.walk(dest) for f in fs)
    assert installed == files_of(deb)


YADE_SCRIPT = r"""
import os, sys
import yade_rbsm, yade_rbsm_tessellation
from yade_rbsm import polygon2d, engines
root = os.environ["DEB_ROOT"]
assert yade_rbsm.__file__.startswith(root), yade_rbsm.__file__
assert yade_rbsm_tessellation.__file__.startswith(root), yade_rbsm_tessellation.__file__
maps = [l.split()[-1] for l in open("/proc/self/maps") if l.rstrip().endswith("libpkg_rbsm.so")]
assert maps and all(os.path.realpath(m).startswith(root) for m in maps), maps
import yade_rbsm.io
rock = RbsmMat(young=1e8, density=2000, frictionAngle=0.6)
O.materials.append(rock)
O.bodies.append(polygon2d([(-5, -1), (5, -1), (5, 0), (-5, 0)], rock, fixed=True))
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], rock))
O.engines = engines(gravity=(0, -9.81, 0))
O.run(200, True)
assert O.interactions.countReal() == 1 and isinstance(O.interactions[0, 1].phys, RbsmPhys)
print("PACKAGE-OK", O.bodies[1].state.pos[1])
"""


def test_yade_runs_the_extracted_package(deb, tmp_path):
    """Plain /usr/bin/yade sees the classes and imports yade_rbsm from the package's files."""
    root = str(tmp_path / "root")
    run(["dpkg-deb", "-x", deb, root])
    # YADE loads every lib*.so under $YADE_PREFIX/lib/x86_64-linux-gnu/yade-double: Debian's own
    # libraries and `py` by symlink, and the plugin from the extracted package.
    prefix = tmp_path / "prefix"
    lib = prefix / "lib/x86_64-linux-gnu/yade-double"
    lib.mkdir(parents=True)
    for f in glob.glob(YADE_LIB_DIR + "/lib*.so") + [YADE_LIB_DIR + "/py"]:
        if os.path.basename(f) != "libpkg_rbsm.so":  # a system-installed copy must not hide the package's
            os.symlink(f, lib / os.path.basename(f))
    os.symlink(os.path.join(root, PLUGIN), lib / "libpkg_rbsm.so")
    script = tmp_path / "script.py"
    script.write_text(YADE_SCRIPT)
    env = dict(os.environ, YADE_PREFIX=str(prefix), DEB_ROOT=root,
               PYTHONPATH=os.path.join(root, DIST), PYTHONDONTWRITEBYTECODE="1")
    out = run(["/usr/bin/yade", "-n", "-x", str(script)], env=env, cwd=str(tmp_path), timeout=300)
    assert "PACKAGE-OK" in out, out
    # the first example the package ships, as a collaborator runs it from /usr/share/doc/yade-rbsm/examples
    example = os.path.join(root, "usr/share/doc/yade-rbsm/examples/first_scene.py")
    out = run(["/usr/bin/yade", "-n", "-x", example], env=env, cwd=str(tmp_path), timeout=300)
    assert "slipping points [True, True]" in out, out[-2000:]
