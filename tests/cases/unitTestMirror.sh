#!/bin/bash
# Case test (no mesh, seconds): tests/unit mirrors src/fdmParticles file for
# file, every source with its unit test (checkUnitTestMirror.py says the
# rules).
source "${0%/*}/caseTestFunctions"

"$FDM_PYTHON" "$caseTemplates/checkUnitTestMirror.py" "$FDM_PROJECT_DIR"
