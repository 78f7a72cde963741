"""Prints the names of the classes a YADE registers, one per line (run by Debian's yade or the launcher)."""
import sys

import yade.system

names = sorted(yade.system.childClasses("Serializable"))
with open(sys.argv[1], "w") as f:
    f.write("\n".join(names) + "\n")
