#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hard-big.sh - the hard-case matrix of tests/e2e/hard.sh on grids 2 and
# 4 times finer in each direction (minutes, not seconds), for make
# check-hard.  The cases and their assertions are hard.sh's; tolerances
# that are discretisation errors (the Hertz radius) shrink with the
# scale there.  Ends with the "N passed, N failed" line of tests/run.sh.
#   tests/hard/hard-big.sh BINDIR
RC_BIN=$(cd "${1:?usage: hard-big.sh BINDIR}" && pwd); export RC_BIN
RC_TOP=$(cd "$(dirname "$0")/../.." && pwd); export RC_TOP
passed=0 failed=0
for scale in ${HARD_SCALES:-2 4}; do
	log=$(mktemp)
	start=$(date +%s)
	HARD_SCALE=$scale sh "$RC_TOP/tests/e2e/hard.sh" >"$log" 2>&1
	status=$?
	line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 1)
	grep -E '^(FAIL|BROKEN)' "$log"
	if [ -z "$line" ]; then
		echo "BROKEN: hard.sh at scale $scale (exit $status)"; tail -n 5 "$log"
		failed=$((failed + 1))
	else
		p=${line%% passed*}; f=${line#*, }; f=${f%% failed*}
		[ "$status" -ne 0 ] && [ "$f" -eq 0 ] && f=1
		passed=$((passed + p)); failed=$((failed + f))
		printf 'hard.sh scale %-3s %s (%ss)\n' "$scale" "$line" $(($(date +%s) - start))
	fi
	rm -f "$log"
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
