#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# run.sh - run every libFuzzer harness for a bounded time (make fuzz).
#   tests/fuzz/run.sh FUZZDIR SECONDS [BINDIR]
# FUZZDIR holds the built harnesses fuzz_<name>; each starts from a seed
# corpus (tests/data, the regression files of tests/data/fuzz/<name>/ and
# small files the tools generate when BINDIR has them), which grows in
# FUZZDIR/corpus-<name> from run to run.  A crash, leak, timeout or
# out-of-memory input is copied to tests/data/fuzz/<name>/ and makes the
# run fail; the time spent never does.  Prints executions per harness.
set -u
fz=$1 secs=$2 bin=${3:-}
top=$(cd "$(dirname "$0")/../.." && pwd)
status=0

seed_read() {
	c=$1
	cp "$top"/tests/data/io_small.* "$top"/tests/data/fuzz/read/* "$c"/ 2>/dev/null
	[ -x "$bin/surfgen" ] || return 0
	for ext in surf npy gsf txt x3p nc; do
		"$bin/surfgen" -q -n 4x3 --seed 7 -o "$c/gen-4x3.$ext" 2>/dev/null
		"$bin/surfgen" -q -n 1 --type flat -o "$c/gen-1.$ext" 2>/dev/null
	done
	[ -x "$bin/gfmd-solve" ] &&
	    "$bin/gfmd-solve" -q -j 1 -p 0.2 --contact "$c/gen-mask.surf" \
		-o /dev/null "$c/gen-4x3.surf" 2>/dev/null
	return 0
}

seed_rows() {
	c=$1
	cp "$top"/tests/data/fuzz/rows/* "$c"/ 2>/dev/null
	[ -x "$bin/surfgen" ] && [ -x "$bin/gfmd-solve" ] || return 0
	"$bin/surfgen" -q -n 8 --seed 7 -o "$c/.s.surf" 2>/dev/null &&
	"$bin/gfmd-solve" -q -j 1 -p 0.1,0.2 -o "$c/gen-rows.tsv" "$c/.s.surf" 2>/dev/null &&
	"$bin/gfmd-solve" -q -j 1 --json -p 0.1 -o "$c/gen-rows.json" "$c/.s.surf" 2>/dev/null
	rm -f "$c/.s.surf"
	return 0
}

for h in "$fz"/fuzz_*; do
	[ -x "$h" ] || continue
	name=${h##*/fuzz_}
	corpus=$fz/corpus-$name
	arts=$fz/artifacts-$name
	log=$fz/fuzz-$name.log
	mkdir -p "$corpus" "$arts"
	rm -f "$arts"/*
	"seed_$name" "$corpus"
	# -timeout: an input slower than 10 s is a hang; -malloc_limit_mb: a
	# reader must never allocate what the input does not hold.
	LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$top/tests/fuzz/lsan.supp" \
	"$h" -max_total_time="$secs" -timeout=10 -malloc_limit_mb=512 \
	    -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
	    -artifact_prefix="$arts/" "$corpus" >"$log" 2>&1
	rc=$?
	runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
	cov=$(grep -E '^#[0-9]+' "$log" | tail -n 1 | sed -n 's/.*\(cov: [0-9]*\).*/\1/p')
	printf 'fuzz_%s: %s executions in %s s, %s, exit %d\n' "$name" \
	    "${runs:-?}" "$secs" "${cov:-cov: ?}" "$rc"
	found=0
	for a in "$arts"/*; do
		[ -f "$a" ] || continue
		found=1
		dest=$top/tests/data/fuzz/$name/${a##*/}
		cp "$a" "$dest"
		echo "fuzz_$name: new regression input $dest"
	done
	if [ "$found" = 1 ] || [ "$rc" -ne 0 ]; then
		status=1
		echo "fuzz_$name: FAILED; see $log"
		grep -E 'ERROR|SUMMARY|runtime error' "$log" | head -n 5
	fi
done
exit "$status"
