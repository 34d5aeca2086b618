"""What an interpreter lacks of what the module needs (python/cmake/choose_interpreter.cmake):
run as `PYTHON interpreter_probe.py MODULE...`, it prints `sys.executable;X.Y;LACKS`, LACKS the
modules of those named that it cannot find and `headers` when its Python.h is missing (the
development headers the extension is compiled against). Modules are looked up, not imported,
so the probe stays quick however heavy the module (Dask's distributed)."""

import importlib.util
import os
import sys
import sysconfig

lacks = [name for name in sys.argv[1:] if importlib.util.find_spec(name) is None]
if not os.path.isfile(os.path.join(sysconfig.get_path("include"), "Python.h")):
    lacks.append("headers")
print(sys.executable, "%d.%d" % sys.version_info[:2], ",".join(lacks), sep=";")
