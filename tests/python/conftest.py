"""pytest configuration for the pure-Python tests.

Puts ``py/`` on sys.path so that ``yade_rbsm.limit_equilibrium`` can be
imported without installing the package and without YADE.  If the package
``__init__`` cannot be imported here (it is owned by the lead and may pull in
compiled parts), the module file is loaded directly under the same name.
"""

import importlib.util
import os
import sys

_HERE = os.path.dirname(os.path.abspath(__file__))
_PY = os.path.normpath(os.path.join(_HERE, "..", "..", "py"))
if _PY not in sys.path:
    sys.path.insert(0, _PY)
sys.path.insert(0, os.path.join(_HERE, "..", "support"))  # verification.record


def load_limit_equilibrium():
    try:
        from yade_rbsm import limit_equilibrium  # noqa: F401

        return limit_equilibrium
    except Exception:  # package __init__ needs YADE or is absent
        name = "yade_rbsm.limit_equilibrium"
        if name in sys.modules:
            return sys.modules[name]
        path = os.path.join(_PY, "yade_rbsm", "limit_equilibrium.py")
        spec = importlib.util.spec_from_file_location(name, path)
        mod = importlib.util.module_from_spec(spec)
        sys.modules[name] = mod
        spec.loader.exec_module(mod)
        return mod
