#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# make install puts a usable library in place: a program outside the
# project (tests/install/consumer.c) is compiled against the installed
# copy through pkg-config alone, runs, and its results are checked; the
# tools and every manual page are installed; uninstall removes them.
. "$RC_TOP/tests/e2e/lib.sh"
prefix="$T_TMP/prefix"
# A make of its own, quiet unless it fails: the release library, whatever
# the calling make had (make check SANITIZE=1 passes SANITIZE down in
# MAKEFLAGS, and an ASan library does not link into a plain program).
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s -C "$RC_TOP" SANITIZE= "$@"; }
if ! mk install PREFIX="$prefix" >"$T_TMP/make.log" 2>&1; then
	fail "make install PREFIX=$prefix: $(tail -n 5 "$T_TMP/make.log")"
	summary; exit 1
fi
pass "make install"
check "library installed" [ -f "$prefix/lib/libroughcontact.a" ]
check "umbrella header installed" [ -f "$prefix/include/roughcontact/roughcontact.h" ]
check "no internal header installed" sh -c "! ls '$prefix/include/roughcontact/' | grep -q -e _internal -e _impl"
check "pkg-config file installed" [ -f "$prefix/lib/pkgconfig/roughcontact.pc" ]
for m in "$RC_TOP"/man/man*/*.[1-9]; do
	sec=$(basename "$(dirname "$m")")
	check "installed $sec/$(basename "$m")" [ -f "$prefix/share/man/$sec/$(basename "$m")" ]
done
check "surfgen installed and runs" "$prefix/bin/surfgen" -n 8 -o "$T_TMP/s.surf"

export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
cflags=$(pkg-config --cflags roughcontact) && libs=$(pkg-config --libs roughcontact)
check "pkg-config knows roughcontact" [ -n "$libs" ]
if ${CC:-cc} -std=c11 -Wall -Wextra -o "$T_TMP/consumer" \
    "$RC_TOP/tests/install/consumer.c" $cflags $libs 2>"$T_TMP/cc.log"; then
	pass "a program builds against the installed library"
	out=$("$T_TMP/consumer" "$T_TMP/c.surf")
	check_status "it runs" 0 "$T_TMP/consumer" "$T_TMP/c2.surf"
	# rms height as asked: the normalisation to 1e-12 (round-off of a sum
	# of 4096 squares)
	check_rel "rms height of the generated surface" \
	    "$(echo "$out" | awk '$1 == "rms_height" { print $2 }')" 0.5 1e-12
	check "written and read back bit for bit" \
	    [ "$(echo "$out" | awk '$1 == "same_values" { print $2 }')" = 1 ]
	check "the file it wrote is a surf file the tools read" \
	    "$prefix/bin/surfstat" -q -o "$T_TMP/st.tsv" "$T_TMP/c.surf"
else
	fail "a program builds against the installed library: $(head -c 600 "$T_TMP/cc.log")"
fi

# The example of roughcontact(3) compiles as printed and gives
# a_r = kappa p* with kappa within [1.6, 2.8] (the paper's range at
# p* = 0.05 with discretisation excess on a 256^2 grid; 2.18 here).
sed -n '/^\.Bd -literal/,/^\.Ed/p' "$RC_TOP/man/man3/roughcontact.3" |
    sed '1d;$d' | sed 's/\\e/\\/g' >"$T_TMP/example.c"
if ${CC:-cc} -std=c11 -Wall -o "$T_TMP/example" "$T_TMP/example.c" \
    $cflags $libs 2>"$T_TMP/cc.log"; then
	pass "the roughcontact(3) example compiles"
	check_range "its a_r at p* = 0.05" \
	    "$("$T_TMP/example" | awk '{ print $2 }')" 0.08 0.14
else
	fail "the roughcontact(3) example compiles: $(head -c 600 "$T_TMP/cc.log")"
fi

mk uninstall PREFIX="$prefix" >/dev/null 2>&1
check "uninstall removes the library" [ ! -e "$prefix/lib/libroughcontact.a" ]
check "uninstall removes the headers" [ ! -e "$prefix/include/roughcontact" ]
check "uninstall removes the tools" [ ! -e "$prefix/bin/surfgen" ]
summary
