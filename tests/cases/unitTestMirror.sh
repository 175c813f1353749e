#!/bin/bash
# Case test (no mesh, seconds): tests/unit mirrors src/fdmParticles file for
# file; sources that act on meshes, fields or Time are listed in
# tests/unit/caseTested with the case tests that run them
# (checkUnitTestMirror.py says the rules).
source "${0%/*}/caseTestFunctions"

"$FDM_PYTHON" "$caseTemplates/checkUnitTestMirror.py" "$FDM_PROJECT_DIR"
