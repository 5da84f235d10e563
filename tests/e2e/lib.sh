# SPDX-License-Identifier: GPL-3.0-or-later
# lib.sh - helpers for the end-to-end shell tests; source it.
# Tools are found in $RC_BIN (set by tests/run.sh); each check counts one
# test and prints FAIL lines with observed and expected values.
set -u
: "${RC_BIN:?RC_BIN not set: run through tests/run.sh}"
PATH="$RC_BIN:$PATH"
T_PASS=0
T_FAIL=0
T_SKIP=0
T_TMP=$(mktemp -d "${TMPDIR:-/tmp}/rce2e.XXXXXX")
trap 'rm -rf "$T_TMP"' EXIT

pass() { T_PASS=$((T_PASS + 1)); [ -n "${TEST_VERBOSE:-}" ] && echo "PASS: $1"; return 0; }
fail() { T_FAIL=$((T_FAIL + 1)); echo "FAIL: $1"; return 0; }
# skip N REASON: N checks that cannot run here, counted and said why
skip() { T_SKIP=$((T_SKIP + $1)); echo "SKIP: $1 check(s): $2"; return 0; }

# have_pty: script(1) is installed and can make a pseudo-terminal (a
# chroot or container without /dev/pts has none)
have_pty() { script -qec true /dev/null >/dev/null 2>&1; }

# check DESC CMD...: passes if the command succeeds
check() { d=$1; shift; if "$@"; then pass "$d"; else fail "$d"; fi; }

# check_status DESC EXPECTED CMD...: the command's exit status
check_status() {
	d=$1; want=$2; shift 2
	"$@" >/dev/null 2>"$T_TMP/stderr"; got=$?
	if [ "$got" = "$want" ]; then pass "$d"; else fail "$d: exit $got, expected $want ($(head -c 300 "$T_TMP/stderr"))"; fi
}

# check_rel DESC OBSERVED EXPECTED RELTOL
check_rel() {
	if awk -v o="$2" -v e="$3" -v t="$4" 'BEGIN { s = e == 0 ? 1 : (e < 0 ? -e : e); d = o - e; if (d < 0) d = -d; exit !(o == o + 0 && d <= t * s) }'; then
		pass "$1"
	else
		fail "$1: observed $2, expected $3, relative tolerance $4"
	fi
}

# check_range DESC OBSERVED LO HI
check_range() {
	if awk -v o="$2" -v lo="$3" -v hi="$4" 'BEGIN { exit !(o + 0 >= lo + 0 && o + 0 <= hi + 0) }'; then
		pass "$1"
	else
		fail "$1: observed $2, expected in [$3, $4]"
	fi
}

# col FILE NAME [ROW]: value of column NAME in data row ROW (default 1) of a TSV
col() {
	awk -F'\t' -v n="$2" -v r="${3:-1}" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == n) c = i; next }
		NR == r + 1 { if (c) print $c; else print "missing-column-" n; exit }' "$1"
}

# amplitude FILE.surf: max - mean of a field (a pressure's amplitude)
amplitude() {
	off=$(head -c 65536 "$1" | grep -a '^data_offset = ' | sed 's/^data_offset = //')
	od -A n -t f8 -v -j "$off" "$1" | tr -s ' ' '\n' | sed '/^$/d' |
	    awk 'NR == 1 || $1 > m { m = $1 } { s += $1 } END { printf "%.17g\n", m - s / NR }'
}

# The last line of every test program: "N passed, N failed", followed by
# ", N skipped" when some checks could not run here.
summary() {
	if [ "$T_SKIP" -gt 0 ]; then
		echo "$T_PASS passed, $T_FAIL failed, $T_SKIP skipped"
	else
		echo "$T_PASS passed, $T_FAIL failed"
	fi
	[ "$T_FAIL" -eq 0 ]
}
