"""Issue 42: the manual builds from the sources by one command (scripts/build_docs.sh, Sphinx with warnings as
errors), its class reference lists every class the plugin registers in YADE (compared with YADE's own class
list, with and without the plugin, and with the YADE_PLUGIN lines of pkg/rbsm), every module of yade_rbsm has
its autodoc section, every Python block of its pages runs verbatim, every script a page includes is run by a
test, its verification page shows the recorded figures, and the pages render (a headless Chromium screenshot of
the index and of a tutorial, looked at by their pixels). There was no manual on 7ea19b2."""
import glob
import json
import os
import re
import shutil
import subprocess

import pytest

from conftest import BUILD, MANUAL, SRC, launcher, manual_pages, python_blocks, run_block

HTML = os.path.join(BUILD, "docs", "html")


@pytest.fixture(scope="module")
def built():
    p = subprocess.run(["bash", os.path.join(SRC, "scripts", "build_docs.sh")], capture_output=True, text=True,
                       timeout=600, env=dict(os.environ, BUILD_DIR=BUILD))
    assert p.returncode == 0, (p.stdout + p.stderr)[-5000:]
    return HTML


def classes_of(yade, tmp):
    out = os.path.join(tmp, os.path.basename(yade) + ".txt")
    p = subprocess.run([yade, "-n", "-x", os.path.join(SRC, "docs", "tools", "yade_classes.py"), out], cwd=tmp,
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr[-2000:]
    return set(open(out).read().split())


def test_reference_lists_every_class_the_plugin_registers(built, tmp_path):
    ours = classes_of(launcher(), str(tmp_path)) - classes_of("/usr/bin/yade", str(tmp_path))
    source = set()
    for f in glob.glob(os.path.join(SRC, "pkg", "rbsm", "*.cpp")):
        for m in re.finditer(r"YADE_PLUGIN\(\((.*?)\)\)", open(f).read(), re.S):
            source |= set(re.findall(r"\w+", m.group(1)))  # YADE_PLUGIN((A)(B)) or YADE_PLUGIN((A))
    html = open(os.path.join(built, "reference", "classes.html"), encoding="utf-8").read()
    listed = set(re.findall(r'<h3>([A-Za-z0-9_]+)<a class="headerlink"', html))  # a section per class
    assert ours == source, "registered by YADE or declared by YADE_PLUGIN only: %s" % sorted(ours ^ source)
    assert listed == ours, "missing: %s, extra: %s" % (sorted(ours - listed), sorted(listed - ours))
    # each with its docstring and its own attributes (RbsmMat.deformable, as a check outside the tests calls it)
    assert "Rigid-Bodies-Spring Model" in html and "deformable" in html and "safetyFactor" in html


def test_every_module_of_the_package_has_its_reference(built):
    html = open(os.path.join(built, "reference", "python.html"), encoding="utf-8").read()
    missing = []
    for f in glob.glob(os.path.join(SRC, "py", "yade_rbsm", "**", "*.py"), recursive=True):
        mod = os.path.relpath(f, os.path.join(SRC, "py"))[:-3].replace(os.sep, ".").replace(".__init__", "")
        if 'id="module-%s"' % mod not in html:
            missing.append(mod)
    assert not missing, "modules without a reference section: %s" % missing
    assert 'id="yade_rbsm.slope.fos"' in html or "yade_rbsm.fos.fos" in html


def test_every_python_block_of_the_manual_runs(tmp_path):
    n = 0
    for page in manual_pages():
        for line, code in python_blocks(page):
            d = tmp_path / str(n)
            d.mkdir()
            p = run_block(code, str(d))
            assert p.returncode == 0 and "Traceback" not in p.stdout + p.stderr, \
                "%s line %d:\n%s" % (os.path.relpath(page, SRC), line, (p.stdout + p.stderr)[-3000:])
            n += 1
    assert n >= 2


def test_included_scripts_exist_and_tests_run_them():
    tests = "".join(open(f, encoding="utf-8").read() for f in glob.glob(os.path.join(SRC, "tests", "**", "test_*.py"),
                                                                        recursive=True))
    included = []
    for page in manual_pages():
        for rel in re.findall(r"```\{literalinclude\} (\S+)", open(page, encoding="utf-8").read()):
            path = os.path.normpath(os.path.join(os.path.dirname(page), rel))
            assert os.path.isfile(path), "%s includes %s, which is missing" % (page, rel)
            included.append(os.path.basename(path))
    assert {"tutorial_jointed_slope.py", "tutorial_soil_slope.py", "landslide_slope.py", "tutorial_water_earthquake.py",
            "mixed_scene_demo.py", "distributed_bricks.py", "first_scene.py"} <= set(included)
    unrun = [s for s in set(included) if '"%s"' % s not in tests and "'%s'" % s not in tests]
    assert not unrun, "scripts the manual shows that no test runs: %s" % unrun


def test_verification_page_is_made_from_the_records(built, tmp_path):
    records = glob.glob(os.path.join(BUILD, "verification", "*.json"))
    html = open(os.path.join(built, "verification.html"), encoding="utf-8").read()
    if not records:
        assert "No test results in this build yet" in html
        return
    for r in records:
        case = json.load(open(r))["case"]
        assert case.split(":")[0].replace("&", "&amp;").replace("'", "’")[:20] in html.replace("'", "’"), case
    # and the generator itself: a record in, a row with its difference out
    (tmp_path / "v").mkdir()
    json.dump(dict(group="G", case="a case", measured=1.01, reference=1.0, source="closed", rtol=0.02, tolerance=None,
                   unit="m", test="t.py::x", commit="abc"), open(str(tmp_path / "v" / "a.json"), "w"))
    subprocess.run(["/usr/bin/python3", os.path.join(SRC, "docs", "tools", "verification_page.py"), str(tmp_path / "v"),
                    str(tmp_path / "v.md")], check=True)
    assert "| a case | 1 m (closed) | 1.01 m | +1.00 % | 2 % | `t.py::x` |" in open(str(tmp_path / "v.md")).read()


@pytest.mark.parametrize("page", ["index.html", "tutorials/jointed_slope.html"])
def test_pages_render(built, tmp_path, page):
    chromium = shutil.which("chromium")
    assert chromium, "chromium is installed by scripts/setup.sh"
    png = str(tmp_path / "page.png")
    subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--window-size=1280,1600",
                    "--screenshot=" + png, "file://" + os.path.join(built, page)], capture_output=True, timeout=180,
                   cwd=str(tmp_path))
    from PIL import Image
    im = Image.open(png).convert("RGB")
    assert im.size == (1280, 1600)
    colours = im.getcolors(1 << 20)
    dark = sum(n for n, (r, g, b) in colours if r + g + b < 200)
    # the theme's dark sidebar, text, and (on the index) the qt view's picture: not a blank or an error page
    assert len(colours) > 500 and 0.1 < dark / (1280 * 1600) < 0.8, (len(colours), dark)
    html = open(os.path.join(built, page), encoding="utf-8").read()
    assert "yade-rbsm" in html and ("jointset_blocks" in html if "tutorials" in page else "Tutorials" in html)
