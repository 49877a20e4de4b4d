"""Generated property-based integration tests (`archlog testgen`): the test model of a configuration
(model.py), message strategies (msgspec.py, strategies.py), the generated files (generate.py), and
the runtime the generated tests import (runtime.py, processes.py, and the scripts in debian/ that run
under Debian's /usr/bin/python3); `archlog replay` (replay.py). See docs/testgen.md."""
