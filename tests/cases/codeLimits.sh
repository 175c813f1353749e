#!/bin/bash
# Case test (no mesh, seconds): no source file in src/ or applications/ over
# 400 lines and no function over 80 lines (checkCodeLimits.py says how
# functions are found).
source "${0%/*}/caseTestFunctions"

"$FDM_PYTHON" "$caseTemplates/checkCodeLimits.py" "$FDM_PROJECT_DIR"
