#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# run.sh - run every C test binary and every end-to-end script, add up
# their "N passed, N failed[, N skipped]" lines and end with the total
# (", N skipped" only when a test could not run here; SKIP lines say why).
# Each test's line is printed as it finishes.  The tests named in
# tests/long.txt (minutes each: the long validations) run only in the
# long set, the others and the manual pages' lint only in the quick one.
#   tests/run.sh BINDIR TESTBINDIR [quick|long|all]   (default all)
RC_BIN=$(cd "$1" && pwd); export RC_BIN
tbin=$2
set_=${3:-all}
top=$(cd "$(dirname "$0")/.." && pwd); export RC_TOP="$top"
# in_set NAME: whether the test NAME belongs to the set being run
in_set() {
	case $set_ in
	all) return 0 ;;
	long) grep -qx "$1" "$top/tests/long.txt" ;;
	*) ! grep -qx "$1" "$top/tests/long.txt" ;;
	esac
}
passed=0 failed=0 skipped=0 broken=""
log=$(mktemp)

run_one() {
	name=$1; shift
	"$@" >"$log" 2>&1
	status=$?
	line=$(grep -E '^[0-9]+ passed, [0-9]+ failed(, [0-9]+ skipped)?$' "$log" | tail -n 1)
	if [ -z "$line" ]; then
		broken="$broken $name"
		failed=$((failed + 1))
		echo "BROKEN: $name (exit $status, no summary line)"; tail -n 5 "$log"
		return
	fi
	p=${line%% passed*}; f=${line#*, }; f=${f%% failed*}
	case $line in
	*skipped) s=${line##*failed, }; s=${s%% skipped}
		grep -E '^SKIP' "$log"
		skipped=$((skipped + s)) ;;
	esac
	if [ "$f" -ne 0 ] || [ "$status" -ne 0 ]; then
		grep -E '^(FAIL|BROKEN)' "$log"
		[ "$f" -eq 0 ] && f=1
	fi
	passed=$((passed + p)); failed=$((failed + f))
	printf '%-28s %s\n' "$name" "$line"
}

for t in "$tbin"/test_*; do
	[ -x "$t" ] || continue
	in_set "$(basename "$t")" || continue
	run_one "$(basename "$t")" "$t"
done
# The tools exit through tool_fail() with their grids still allocated,
# which LeakSanitizer would report on every failure path; leaks are checked
# in the library's unit tests above and by valgrind on a whole pipeline.
for s in "$top"/tests/e2e/*.sh; do
	case $s in */lib.sh) continue ;; esac
	in_set "$(basename "$s")" || continue
	ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
	    run_one "$(basename "$s")" sh "$s"
done
# Man pages lint clean, when mandoc is here.
if [ "$set_" != long ] && command -v mandoc >/dev/null 2>&1; then
	for m in "$top"/man/man*/*.[1-9]; do
		[ -f "$m" ] || continue
		if out=$(mandoc -Tlint -Wwarning "$m" 2>&1) && [ -z "$out" ]; then
			passed=$((passed + 1))
		else
			failed=$((failed + 1)); echo "FAIL: mandoc -Tlint $(basename "$m"): $out"
		fi
	done
fi
rm -f "$log"
if [ "$skipped" -gt 0 ]; then
	echo "$passed passed, $failed failed, $skipped skipped"
else
	echo "$passed passed, $failed failed"
fi
[ "$failed" -eq 0 ]
