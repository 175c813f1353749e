#!/bin/bash
# Case test (no mesh, seconds): README's "Reference" lists every keyword the
# solvers read (by solver) and every option of the solvers and utilities,
# and nothing they do not read (checkKeywordReference.py says how the code
# is read).
source "${0%/*}/caseTestFunctions"

"$FDM_PYTHON" "$caseTemplates/checkKeywordReference.py" "$FDM_PROJECT_DIR"
