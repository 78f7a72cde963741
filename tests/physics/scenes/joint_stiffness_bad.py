"""RbsmMat.jointKn / jointKs refused when negative or NaN, by every way of setting them; returns the messages."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit

p = params()
attr, value = p["attr"], p["value"]
out = {}
for how in ("ctor", "assign", "updateAttrs"):
    try:
        if how == "ctor":
            RbsmMat(**{attr: value})
        elif how == "assign":
            m = RbsmMat()
            setattr(m, attr, value)
        else:
            RbsmMat().updateAttrs({attr: value})
        out[how] = "accepted"
    except Exception as e:
        out[how] = str(e)
emit(out)
