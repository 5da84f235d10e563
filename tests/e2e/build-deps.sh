# SPDX-License-Identifier: GPL-3.0-or-later
# build-deps.sh - a missing build dependency stops make before compiling,
# naming the Debian packages to install (not a compiler error on fftw3.h).
. "$RC_TOP/tests/e2e/lib.sh"
if ! command -v make >/dev/null 2>&1; then
	echo "SKIP: make not installed (apt-get install make)"
	echo "$T_PASS passed, $T_FAIL failed"
	exit 0
fi
# -n: nothing is built or changed in the tree; the check runs when the
# Makefile is read.  MAKEFLAGS from an outer make (check, -j) is dropped.
mk() { MAKEFLAGS= make -n -C "$RC_TOP" "$@" > "$T_TMP/out" 2>&1; }

mk all; st=$?
check "all dependencies present: make -n succeeds (exit $st)" [ "$st" -eq 0 ]
check "no dependency message when all are present" \
    sh -c "! grep -q 'not found' '$T_TMP/out'"

mk PKG_CONFIG=false all; st=$?
check "every package missing: make stops with exit 2 (got $st)" [ "$st" -eq 2 ]
check "names the pkg-config packages" grep -q 'not found: fftw3 gsl libpng libzip libxml-2.0 netcdf zlib yaml-0.1' "$T_TMP/out"
check "names the Debian packages to install" \
    grep -q 'apt-get install -y libfftw3-dev libgsl-dev libnetcdf-dev libpng-dev libxml2-dev libyaml-dev libzip-dev zlib1g-dev$' "$T_TMP/out"
check "stops before any compiler command" sh -c "! grep -q -- '-c -o' '$T_TMP/out'"

mk 'PKGS=fftw3 gsl nonexistent' all; st=$?
check "one package missing: exit 2 (got $st)" [ "$st" -eq 2 ]
check "names only the missing one" grep -q 'not found: nonexistent$' "$T_TMP/out"
check "a package with no known Debian name is said so" \
    grep -q 'no Debian package known for: nonexistent' "$T_TMP/out"

mk PKG_CONFIG=/nonexistent/pkg-config all; st=$?
check "pkg-config itself missing: exit 2 (got $st)" [ "$st" -eq 2 ]
check "and it is named with its package" grep -q 'apt-get install -y .*pkg-config' "$T_TMP/out"

mk CC=/nonexistent/cc all; st=$?
check "no compiler: exit 2 (got $st)" [ "$st" -eq 2 ]
check "build-essential named" grep -q 'apt-get install -y build-essential' "$T_TMP/out"

mk PKG_CONFIG=false clean; st=$?
check "make clean needs no library (exit $st)" [ "$st" -eq 0 ]
echo "$T_PASS passed, $T_FAIL failed"
[ "$T_FAIL" -eq 0 ]
