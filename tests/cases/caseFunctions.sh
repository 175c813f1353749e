#!/bin/bash
# Case test (no mesh, seconds): the restart guard removeIncompleteWrites of
# etc/caseFunctions removes a write that a kill cut short (serial and
# decomposed) and keeps whole writes; setAdhesion sets the adhesive
# contact law; setTimeStep keeps records and writes in strain
# (checkCaseFunctions.py).
source "${0%/*}/caseTestFunctions"

"$FDM_PYTHON" "$caseTemplates/checkCaseFunctions.py" -v 2>&1 | tail -n 8
exit "${PIPESTATUS[0]}"
