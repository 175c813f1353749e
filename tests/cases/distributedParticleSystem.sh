#!/bin/bash
# Case test (issue 38): the particle system of eq 2.43 solved by subdomain
# (fdm::distributedParticleSystem) gives the velocities of the whole system
# solved on one rank (fdm::particleVelocitySystem).  The benchmark
# validation/benchmarks/particleDistribution/distributedSolve cuts the
# periodic packing of particleSystemScaling (216 and 1000 spheres, sub-grid
# pairs with gap < 0.3 a) into slabs along x, one per rank; each rank owns
# the particles of its slab, holds their partners owned elsewhere as ghosts
# and solves its rows with the others to a CG tolerance of 1e-12.  On 1, 2
# and 3 ranks the largest difference from the whole system's solution must
# stay below 1e-9 of the largest velocity, and on 2 and 3 ranks the ranks
# must hold ghosts (pairs across the cuts).
source "${0%/*}/caseTestFunctions"

work=$(caseWorkDir distributedParticleSystem)
bench="$FDM_PROJECT_DIR/validation/benchmarks/particleDistribution"
(cd "$bench" && wmake -s . > "$work/log.wmake" 2>&1) \
    || { echo "FAILED: building distributedSolve ($work/log.wmake)"; tail -20 "$work/log.wmake"; exit 1; }
cd "$work" || exit 1
runLogged distributedSolve -lattice "(6 10)" -tolerance 1e-12 -compare \
    || exit 1
for n in 2 3
do
    log=log.distributedSolve.$n
    mpirun -np $n --oversubscribe distributedSolve -lattice "(6 10)" \
        -tolerance 1e-12 -compare -parallel > $log 2>&1 \
        || { echo "FAILED: mpirun -np $n distributedSolve ($work/$log)"; tail -20 $log; exit 1; }
done

status=0
for log in log.distributedSolve log.distributedSolve.2 log.distributedSolve.3
do
    # | N | ranks | owned | ghosts | search | assembly | solve | its | difference |
    rows=$(grep -c "^| [0-9]" $log)
    [ "$rows" -eq 2 ] || { echo "FAILED: $log has $rows result rows, not 2"; status=1; }
    while read -r N ranks owned ghosts its diff
    do
        ok=$(awk -v d="$diff" -v r="$ranks" -v g="$ghosts" \
            'BEGIN { print (d >= 0 && d < 1e-9 && (r == 1 || g > 0)) ? 1 : 0 }')
        echo "   $N spheres on $ranks rank(s): $ghosts ghosts, $its CG iterations, difference $diff"
        [ "$ok" = 1 ] || { echo "FAILED: $log"; status=1; }
    done < <(grep "^| [0-9]" $log | awk -F'|' '{ print $2, $3, $4, $5, $9, $10 }')
done
exit $status
