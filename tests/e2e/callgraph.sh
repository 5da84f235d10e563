#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# callgraph.sh - the library's files are layered: no object file of the
# library uses (nm: undefined) a symbol defined in a file that, directly
# or around a longer loop, uses one of its own.  The file-level graph
# "A uses a symbol defined in B" is read from the objects with nm; each
# strongly connected set of two or more files is a circle and fails,
# named by one shortest cycle with the symbol of each step.  The checker
# is first shown a circle of its own making (two objects compiled here
# that call each other), which it must find.
. "$RC_TOP/tests/e2e/lib.sh"

# The objects: those of the library archive of the build that made
# $RC_BIN (build/san/librc.a for SANITIZE=1, whose tools are in
# build/san/bin), else build/librc.a, unpacked (a build directory can
# hold stale objects of files since moved); or those under $RC_OBJ.
objdir=""
if [ -n "${RC_OBJ:-}" ]; then
	objdir=$RC_OBJ
else
	for a in "$RC_BIN/../librc.a" "$RC_TOP/build/librc.a"; do
		if [ -f "$a" ]; then
			mkdir -p "$T_TMP/lib" && (cd "$T_TMP/lib" && ar x "$a") && objdir="$T_TMP/lib"
			break
		fi
	done
fi

# symbols DIR: "D file sym" and "U file sym" for the objects under DIR
# (the MPI build's lib/mpi aside), file the path under DIR
symbols() {
	find "$1" -name '*.o' ! -path '*/mpi/*' | sort | while read -r o; do
		f=${o#"$1"/}
		nm -g --defined-only "$o" | awk -v f="$f" 'NF >= 3 { print "D", f, $3 }'
		nm -u "$o" | awk -v f="$f" '{ print "U", f, $NF }'
	done
}

# edges DIR: "a.o b.o sym", a.o uses sym defined in b.o, one line per pair
edges() {
	symbols "$1" | awk '$1 == "D" { def[$3] = $2; next } { use[++u] = $2 " " $3 }
	END { for (k = 1; k <= u; k++) { split(use[k], p, " ")
		if ((p[2] in def) && def[p[2]] != p[1] && !((p[1], def[p[2]]) in e)) {
			e[p[1], def[p[2]]] = 1; print p[1], def[p[2]], p[2] } } }'
}

# circles DIR: prints one line per circle, "a.o -> b.o (sym) -> a.o
# (sym)", for the objects under DIR
circles() {
	symbols "$1" | awk '
	$1 == "D" { def[$3] = $2; if (!($2 in id)) { id[$2] = ++n; name[n] = $2 } ; next }
	{ if (!($2 in id)) { id[$2] = ++n; name[n] = $2 }; use[++u] = $2 SUBSEP $3 }
	END {
		for (k = 1; k <= u; k++) {
			split(use[k], p, SUBSEP)
			if (!(p[2] in def) || def[p[2]] == p[1]) continue
			a = id[p[1]]; b = id[def[p[2]]]
			if (!((a, b) in e)) { e[a, b] = p[2]; r[a, b] = 1 }
		}
		# transitive closure (Warshall): r[a, b] when a reaches b
		for (k = 1; k <= n; k++) for (i = 1; i <= n; i++) if ((i, k) in r)
			for (j = 1; j <= n; j++) if ((k, j) in r) r[i, j] = 1
		for (s = 1; s <= n; s++) {
			if (done[s] || !((s, s) in r)) continue
			# the circle of s: every t with s -> t -> s
			for (t = 1; t <= n; t++) if ((s, t) in r && (t, s) in r) { done[t] = 1; in_c[t] = s }
			# one shortest cycle through s, by breadth-first search in the circle
			delete prev; delete seen; h = 1; q[1] = s; qn = 1; found = 0
			while (h <= qn && !found) {
				x = q[h++]
				for (y = 1; y <= n && !found; y++) {
					if (!((x, y) in e) || in_c[y] != s) continue
					if (y == s) { last = x; found = 1; break }
					if (!(y in seen)) { seen[y] = 1; prev[y] = x; q[++qn] = y }
				}
			}
			line = name[s] " (" e[last, s] ")"; y = last
			while (y != s) { line = name[y] " (" e[prev[y], y] ") -> " line; y = prev[y] }
			line = name[s] " -> " line
			# the steps name the symbol that the file before the arrow uses
			m = ""; for (t = 1; t <= n; t++) if (in_c[t] == s) m = m " " name[t]
			print line "    [circle:" m " ]"
		}
	}'
}

# The checker finds a circle it is shown: a.o calls b.o calls a.o,
# and c.o (called by a.o only) is on none.
self="$T_TMP/self"
mkdir -p "$self"
cat >"$self/a.c" <<'EOF'
int rc_cg_b(int);
int rc_cg_c(int);
int rc_cg_a(int x) { return x > 0 ? rc_cg_b(x - 1) + rc_cg_c(x) : 0; }
EOF
cat >"$self/b.c" <<'EOF'
int rc_cg_a(int);
int rc_cg_b(int x) { return rc_cg_a(x); }
EOF
cat >"$self/c.c" <<'EOF'
int rc_cg_c(int x) { return x; }
EOF
if ${CC:-cc} -c -o "$self/a.o" "$self/a.c" && ${CC:-cc} -c -o "$self/b.o" "$self/b.c" &&
    ${CC:-cc} -c -o "$self/c.o" "$self/c.c"; then
	got=$(circles "$self")
	check "the checker finds a circle of two files" [ "$(printf '%s\n' "$got" | grep -c .)" = 1 ]
	case $got in
	"a.o -> b.o (rc_cg_b) -> a.o (rc_cg_a)    [circle: a.o b.o ]") pass "the circle is named with its symbols" ;;
	*) fail "the circle is named with its symbols: got '$got'" ;;
	esac
	rm "$self/b.o"
	check "no circle without it" [ -z "$(circles "$self")" ]
else
	skip 3 "no C compiler to build the checker's own circle"
fi

# The solver's layers, top down (lib/solver/solver_impl.h): a file uses files
# of lower layers only, and of its own layer unless that is the
# minimisers' (a method does not call another).
layer_of() {
	case ${1##*/} in
	solver.o|solver_approach.o|solver_fire_adh.o|solver_fire_adh_free.o) echo "4 drivers" ;;
	solver_fire.o|solver_fire_free.o|solver_cg.o|solver_fire_adh_pass.o) echo "3 minimisers" ;;
	solver_fire_loop.o|solver_operator.o|solver_wall.o|solver_hardness.o|solver_measure.o|adhesion.o) echo "2 parts" ;;
	solver_opts.o|elastic*.o|layer.o|love.o|fft.o|threads.o|rc_err.o) echo "1 below" ;;
	*) echo "" ;;
	esac
}
# layering DIR: one line per edge against the layers
layering() {
	edges "$1" | while read -r a b sym; do
		la=$(layer_of "$a"); lb=$(layer_of "$b")
		[ -n "$la" ] && [ -n "$lb" ] || continue
		if [ "${la%% *}" -lt "${lb%% *}" ] ||
		    { [ "$la" = "$lb" ] && [ "${la#* }" = minimisers ]; }; then
			echo "$a (${la#* }) uses $sym of $b (${lb#* })"
		fi
	done
}

if [ -z "$objdir" ]; then
	fail "no library archive $RC_BIN/../librc.a or $RC_TOP/build/librc.a: build first"
else
	nobj=$(find "$objdir" -name '*.o' ! -path '*/mpi/*' | grep -c .)
	check "the library has objects to check ($nobj)" [ "$nobj" -gt 20 ]
	found=$(circles "$objdir")
	if [ -z "$found" ]; then
		pass "no file of the library is on a call circle"
	else
		printf '%s\n' "$found" | while read -r c; do echo "CIRCLE: $c"; done
		fail "call circles in the library: $(printf '%s\n' "$found" | grep -c .)"
	fi
	n_solver=0
	for f in solver solver_fire solver_cg solver_measure solver_operator; do
		[ -f "$(find "$objdir" -name "$f.o" | head -n 1)" ] && n_solver=$((n_solver + 1))
	done
	check "the solver's layered files are there ($n_solver of 5)" [ "$n_solver" = 5 ]
	up=$(layering "$objdir")
	if [ -z "$up" ]; then
		pass "the solver's files call down their layers only"
	else
		printf '%s\n' "$up" | while read -r c; do echo "UPWARD: $c"; done
		fail "calls up or across the solver's layers: $(printf '%s\n' "$up" | grep -c .)"
	fi
	# make fuzz links each harness from the sources the Makefile lists,
	# not the archive: every library symbol their objects use must be
	# defined by one of them (io_dl.c and fft.c were missing: undefined
	# rc__dl_xml, rc_fft_huge ...).
	for v in FUZZ_READ_SRC FUZZ_ROWS_SRC; do
		srcs=$(printf 'rc-print-src:\n\t@echo $(%s)\n' "$v" |
		    make -s --no-print-directory -C "$RC_TOP" -f Makefile -f - rc-print-src)
		missing=$(symbols "$objdir" | awk -v list="$srcs" '
		BEGIN { n = split(list, s, " "); for (k = 1; k <= n; k++) {
			f = s[k]; sub(/.*\//, "", f); sub(/\.c$/, ".o", f); in_list[f] = 1 } }
		$1 == "D" { def[$3] = $2; next }
		($2 in in_list) { use[$3] = $2 }
		END { for (y in use) if ((y in def) && !(def[y] in in_list))
			print use[y] " uses " y " of " def[y] }' | sort)
		if [ -n "$srcs" ] && [ -z "$missing" ]; then
			pass "make fuzz: $v defines every library symbol its files use"
		else
			printf '%s\n' "$missing" | head -n 5 | sed 's/^/MISSING: /'
			fail "make fuzz: $v lacks $(printf '%s\n' "$missing" | grep -c .) symbols"
		fi
	done
fi
summary
