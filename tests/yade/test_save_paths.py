"""Issue 34, item 12: O.save to a missing directory, a read-only place or a full disk said "output stream
error" without the path; O.save('') "f of file to save has zero length"; and O.save of a directory returned
without a word, having written nothing (measured on ff4ddbd: O.save('/tmp') "saved"). With yade_rbsm imported
each names the path and the problem; a good path and O.saveTmp work as before."""
import os

from yaderun import results, run_yade

SCENE = """
import os
import yade_rbsm
from yade_rbsm import polygon2d
mat = RbsmMat(young=1e8, density=2000)
O.materials.append(mat)
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], mat))
out = {}
for p in [WORK, os.path.join(WORK, "missing", "s.xml"), "", "/proc/s.xml", os.path.join(WORK, "s.yade.gz")]:
    try:
        O.save(p)
        out[p] = "saved"
    except Exception as e:
        out[p] = "%s: %s" % (type(e).__name__, e)
O.saveTmp("slot")
O.loadTmp("slot")
report(out=out, bodies=len(O.bodies))
"""


def test_save_names_the_path_and_the_problem(tmp_path):
    work = str(tmp_path)
    p = run_yade("WORK = %r\n" % work + SCENE)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    (r,) = results(p)
    out = r["out"]
    print(out)
    assert out[work].startswith("ValueError") and "is a directory" in out[work] and work in out[work]
    missing = os.path.join(work, "missing", "s.xml")
    assert out[missing].startswith("ValueError") and "does not exist" in out[missing] and os.path.join(work, "missing") in out[missing]
    assert out[""].startswith("ValueError") and "give a file name" in out[""]
    assert out["/proc/s.xml"].startswith(("OSError", "ValueError")) and "/proc/s.xml" in out["/proc/s.xml"]
    assert out[os.path.join(work, "s.yade.gz")] == "saved" and os.path.getsize(os.path.join(work, "s.yade.gz")) > 0
    assert r["bodies"] == 1  # O.saveTmp / loadTmp untouched


BAD_NAMES = """
import os
import yade_rbsm
from yade_rbsm import polygon2d
mat = RbsmMat(young=1e8, density=2000)
O.materials.append(mat)
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], mat))
os.symlink(os.path.join(WORK, "nowhere", "x"), os.path.join(WORK, "dangling.xml"))
out = {}
for key, p in [("nul", os.path.join(WORK, "bad\\0name.xml")), ("long", os.path.join(WORK, "a" * 300 + ".xml")),
               ("dangling", os.path.join(WORK, "dangling.xml"))]:
    try:
        O.save(p)
        out[key] = "saved"
    except Exception as e:
        out[key] = "%s: %s" % (type(e).__name__, e)
out["files"] = sorted(os.listdir(WORK))
report(out=out)
"""


def test_save_refuses_names_no_file_can_have(tmp_path):
    """The closing adversarial pass (issue 34): O.save('bad\\0name.xml') returned normally and wrote a file called
    'bad'; a 300-character name and a dangling symbolic link said "a full disk, or a file system that refused
    it?". Each is refused before anything is written, saying what is wrong with the name."""
    p = run_yade("WORK = %r\n" % str(tmp_path) + BAD_NAMES)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    (r,) = results(p)
    out = r["out"]
    print(out)
    assert out["nul"].startswith("ValueError") and "NUL" in out["nul"]
    assert out["long"].startswith("ValueError") and "255" in out["long"]
    assert out["dangling"].startswith("ValueError") and "symbolic link" in out["dangling"] and "nowhere" in out["dangling"]
    assert out["files"] == ["dangling.xml"]  # nothing written
