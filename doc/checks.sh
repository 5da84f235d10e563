#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# checks.sh - the checks of a C test whose descriptions match a pattern, as
# a Markdown table of what each measured: the test runs once per make doc
# with TEST_VERBOSE=1 (tests/testlib.c then prints every passed check with
# its observed and expected values, error and tolerance); its output is
# kept in DOC_CACHE for the other sections that quote it.
# Checks of a status alone (an integer "observed 0, expected 0", or a
# description ending in converges, made or refused) are left out: they
# measure nothing.
#   sh doc/checks.sh TEST [ERE]
# TEST: a binary of RC_TESTS (test_free) or a script of tests/e2e
# (free.sh), whose check lines print the same way under TEST_VERBOSE.
set -u
: "${RC_TESTS:?RC_TESTS not set (doc/gen.sh sets it)}"
: "${DOC_CACHE:?DOC_CACHE not set (doc/gen.sh sets it)}"
: "${RC_TOP:?RC_TOP not set (doc/gen.sh sets it)}"
t=$1
pat=${2:-.}
out=$DOC_CACHE/$t.out
if [ ! -f "$out" ]; then
	case $t in
	*.sh) TEST_VERBOSE=1 sh "$RC_TOP/tests/e2e/$t" > "$out.tmp" 2>&1 ;;
	*) TEST_VERBOSE=1 "$RC_TESTS/$t" > "$out.tmp" 2>&1 ;;
	esac
	status=$?
	mv "$out.tmp" "$out"
	echo "$status" > "$out.status"
fi
summary=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$out" | tail -n 1)
grep -E '^(PASS|FAIL): ' "$out" | grep -v -E ': observed -?[0-9]+, expected -?[0-9]+$|(converges|made|refused)$' |
    grep -E -e "$pat" > "$DOC_CACHE/sel" || {
	echo "checks.sh: $t: no check matches '$pat'" >&2; exit 1; }
# "PASS: what: observed X, expected Y, relative error E, tolerance T", or
# "..., error E, tolerance T", "..., expected in [LO, HI]", "observed N,
# expected N" (integers), or the description alone (its numbers inside).
awk -v test="$t" -v summary="$summary" '
function num(s) { return (s ~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/ && s != ".") ? sprintf("%.4g", s) : s }
BEGIN { print "| check | observed | expected | error | tolerance | |"
	print "|---|---|---|---|---|---|" }
{
	res = $0 ~ /^PASS/ ? "pass" : "**FAIL**"
	sub(/^(PASS|FAIL): /, "")
	obs = ex = err = tol = ""
	i = index($0, ": observed ")
	if (i > 0) {
		d = substr($0, i + 11); what = substr($0, 1, i - 1)
		n = split(d, f, ", ")
		obs = num(f[1])
		for (k = 2; k <= n; k++) {
			if (f[k] ~ /^expected in \[/) { lo = f[k]; sub(/^expected in \[/, "", lo)
				hi = f[k + 1]; sub(/\]$/, "", hi); ex = "[" num(lo) ", " num(hi) "]"; k++ }
			else if (f[k] ~ /^expected /) { v = f[k]; sub(/^expected /, "", v); ex = num(v) }
			else if (f[k] ~ /^relative error /) { v = f[k]; sub(/^relative error /, "", v); err = num(v) " (rel.)" }
			else if (f[k] ~ /^error /) { v = f[k]; sub(/^error /, "", v); err = num(v) }
			else if (f[k] ~ /^tolerance /) { v = f[k]; sub(/^tolerance /, "", v); tol = num(v) }
		}
	} else
		what = $0
	gsub(/\|/, "\\|", what); gsub(/\*/, "\\*", what)
	printf "| %s | %s | %s | %s | %s | %s |\n", what, obs, ex, err, tol, res
}
END { cmd = test ~ /\.sh$/ ? "TEST_VERBOSE=1 RC_BIN=bin RC_TOP=. sh tests/e2e/" test : "TEST_VERBOSE=1 build/tests/" test
	printf "\n%d checks shown (`%s`: %s in all)\n", NR, cmd, summary }
' "$DOC_CACHE/sel"
