#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# overwrite.sh - an output the shell's `>` would not replace is refused
# before the work (issue 27): a write-protected file in a writable
# directory, and another user's world-writable file in a sticky directory
# (/tmp), where rename(2) fails only after the whole solve.  Root ignores
# permissions, so as root the tools run as user nobody (setpriv).
. "$RC_TOP/tests/e2e/lib.sh"
T=$T_TMP
cd "$T" || exit 1

surfgen -q -n 32 -o s.surf
RUNAS=""
if [ "$(id -u)" = 0 ]; then
	if chmod 755 "$T" && command -v setpriv >/dev/null 2>&1 &&
	    setpriv --reuid=65534 --regid=65534 --clear-groups -- \
	    surfstat -q s.surf >/dev/null 2>&1; then
		RUNAS="setpriv --reuid=65534 --regid=65534 --clear-groups --"
	else
		skip 8 "root, and user nobody cannot run the tools here (no setpriv, or the build is not world-readable)"
		summary
		exit 0
	fi
fi

# A write-protected file in a directory the user may write.
mkdir w && echo precious > w/ro.tsv && chmod 444 w/ro.tsv
[ -n "$RUNAS" ] && chown -R 65534:65534 w
# shellcheck disable=SC2086
check_status "gfmd-solve -o a write-protected file: exit 2" 2 \
    $RUNAS gfmd-solve -q -p 0.05 -o w/ro.tsv s.surf
check "  says so" grep -q 'w/ro.tsv: Permission denied (the file is write-protected' "$T_TMP/stderr"
check "  the file is kept" test "$(cat w/ro.tsv)" = precious
# shellcheck disable=SC2086
check_status "surfgen -o a write-protected file: exit 2" 2 \
    $RUNAS surfgen -q -n 8 -o w/ro.tsv
check "  the file is kept" test "$(cat w/ro.tsv)" = precious
# shellcheck disable=SC2086
check_status "surfstat -o a new file in that directory: exit 0" 0 \
    $RUNAS surfstat -q -o w/new.tsv s.surf

# Another user's world-writable file in a sticky directory of another
# user: only when the runner is nobody (as root) can this be set up.
if [ -n "$RUNAS" ]; then
	mkdir st && chmod 1777 st && echo theirs > st/f.tsv && chmod 666 st/f.tsv
	# shellcheck disable=SC2086
	check_status "gfmd-solve -o another user's file in a sticky directory: exit 2" 2 \
	    $RUNAS gfmd-solve -q -p 0.05 -o st/f.tsv s.surf
	check "  says so before the solve" grep -q 'belongs to another user in the sticky directory' "$T_TMP/stderr"
	check "  the file is kept" test "$(cat st/f.tsv)" = theirs
else
	skip 3 "not root: another user's file in a sticky directory cannot be made here"
fi
summary
