#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# field.sh - the measured-data path over every file of a folder of real
# instrument files (a field corpus), with default options:
#   read        surfstat --channels FILE; surfstat --iso FILE (Sq over the
#               valid points of the default channel)
#   level, fill surfwarp --detrend plane --fill
#   analyse     surfstat --iso and surfstat --fit of the levelled map
#   contact     gfmd-solve -p 0.01,0.05 (free boundaries, default method)
#   two grids   where min(nx, ny) >= 64: the levelled map coarsened 2x
#               (surfwarp --resample, spacing 2 dx x 2 dy) solved the
#               same way, both into contact-stats (a_r extrapolated)
# One row per file; a file that cannot be read is a row with the tool's
# message.  "read" compares nx, ny, lx, ly (in metres), the unit scale and
# the rms of the heights (in metres; Gwyddion's rms is over the valid
# points, as surfstat --iso's Sq) with the manifest's row of the same
# channel (title, else number), relative 1e-6: "right", "wrong(FIELDS)",
# "unchecked" (no manifest row: Gwyddion cannot read the file) or
# "refused"; a line scan not uniformly spaced, which has no --iso, is
# read by surfstat's scalar row (its hrms in the note), unchecked.  Every command runs under timeout; each gfmd-solve run (both
# pressures) is bounded by FIELD_TIMEOUT CPU seconds (default 90: its user
# and system time from /proc, so that a loaded machine does not stop it
# early; wall seconds where /proc is missing), by 10 FIELD_TIMEOUT wall
# seconds, and, if FIELD_MAX_ITER is set, by --max-iter: gfmd-solve gets
# SIGTERM and writes the rows it finished; a pressure stopped by a bound
# has its iterations marked '*' and the note says which bound stopped it.
#   sh bench/field.sh [options] DIR       (make field FIELD=DIR)
#   -m FILE      manifest (default DIR/../MANIFEST.tsv or DIR/MANIFEST.tsv
#                if present): columns file gwyddion_reads channel title nx
#                ny lx ly xy_unit z_unit masked rms, one row per channel
#   -o FILE      also write the rows as TSV (unaligned) to FILE
#   --solvers    instead: iterations and seconds per file of FIRE and CG
#                on free boundaries and of periodic FIRE, p* = 0.01, 0.05
# Environment: RC_BIN (tools; default bin), FIELD_TIMEOUT, FIELD_MAX_ITER,
# FIELD_THREADS (gfmd-solve -j, default 1).  Without DIR it says so and
# exits 0 (make bench runs every bench/*.sh).  Never fails on time.
set -u
RC_BIN=${RC_BIN:-bin}
TLIM=${FIELD_TIMEOUT:-90}
MAXIT=${FIELD_MAX_ITER:-}
THREADS=${FIELD_THREADS:-1}
STEP_TLIM=300	# any other command (readers, levelling, fit)
PRESSURES=0.01,0.05
MIN_COARSE=64	# the coarse grid is at least 32 points a side

MANIFEST="" TSV_OUT="" MODE=path DIR=${FIELD:-}
while [ $# -gt 0 ]; do
	case $1 in
	-m|-o) [ $# -ge 2 ] || { echo "field.sh: $1 needs a file" >&2; exit 2; }
		if [ "$1" = -m ]; then MANIFEST=$2; else TSV_OUT=$2; fi
		shift 2 ;;
	--solvers) MODE=solvers; shift ;;
	-h|--help) sed -n '3,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
	-*) echo "field.sh: $1: unknown option (-m FILE, -o FILE, --solvers)" >&2; exit 2 ;;
	*) DIR=$1; shift ;;
	esac
done
if [ -z "$DIR" ]; then
	echo "field.sh: no corpus folder given (sh bench/field.sh DIR, or make field FIELD=DIR); nothing measured"
	exit 0
fi
[ -d "$DIR" ] || { echo "field.sh: $DIR: not a folder" >&2; exit 2; }
for t in surfstat surfwarp gfmd-solve contact-stats; do
	[ -x "$RC_BIN/$t" ] || { echo "field.sh: $RC_BIN/$t: no such tool (set RC_BIN)" >&2; exit 2; }
done
if [ -z "$MANIFEST" ]; then
	for m in "$DIR/../MANIFEST.tsv" "$DIR/MANIFEST.tsv"; do
		[ -f "$m" ] && { MANIFEST=$m; break; }
	done
fi
[ -z "$MANIFEST" ] || [ -r "$MANIFEST" ] || { echo "field.sh: $MANIFEST: cannot read" >&2; exit 2; }
command -v timeout >/dev/null 2>&1 || { echo "field.sh: needs timeout(1) to bound the solves" >&2; exit 2; }
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rcfield.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
[ -n "$TSV_OUT" ] && : >"$TSV_OUT"

SOLVE_OPTS="-q -j $THREADS"
[ -n "$MAXIT" ] && SOLVE_OPTS="$SOLVE_OPTS --max-iter $MAXIT"
CLK=$(getconf CLK_TCK 2>/dev/null || echo 100)
if [ -r /proc/self/stat ]; then TKIND="CPU s ($((10 * TLIM)) wall s)"; else TKIND="s"; fi
BOUND="$TLIM $TKIND per gfmd-solve run${MAXIT:+, --max-iter $MAXIT}"

# col TSV NAME [ROW]: the value of column NAME in data row ROW (default 1)
col() {
	awk -F '\t' -v c="$2" -v r="${3:-1}" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) k = i; next }
		NR == r + 1 && k { print $k; exit }' "$1"
}
# msg FILE [NAME]: the last message line of a tool's stderr (its error,
# after any warnings), without the tool and path prefixes and tabs; a
# long one keeps its start and its end (the why)
msg() {
	grep -v '^$' "$1" | tail -n 1 | sed "s|^[a-z-]*: ||; s|^[^ :]*$2: ||; s|	| |g" |
	    awk '{ print (length($0) > 220 ? substr($0, 1, 80) " ... " substr($0, length($0) - 134) : $0) }'
}
# sig X: X to 4 significant digits (a_r, seconds)
sig() { awk -v x="$1" 'BEGIN { if (x == "" || x == "-") print "-"; else printf "%.4g\n", x }'; }

# Columns of a row, tab-separated; the aligned form pads them.
HEAD_PATH="file	format	grid	read	Sq_lev	fit	it_0.01	s_0.01	a_r_0.01	it_0.05	s_0.05	a_r_0.05	a_ext_0.01	a_ext_0.05	note"
HEAD_SOLV="file	grid	fire_it_0.01	fire_s_0.01	fire_it_0.05	fire_s_0.05	cg_it_0.01	cg_s_0.01	cg_it_0.05	cg_s_0.05	per_it_0.01	per_s_0.01	per_it_0.05	per_s_0.05	note"
emit() {	# emit TSV-ROW: aligned on stdout, raw to -o FILE
	[ -n "$TSV_OUT" ] && printf '%s\n' "$1" >>"$TSV_OUT"
	printf '%s\n' "$1" | awk -F '\t' -v mode="$MODE" '{
		if (mode == "path") split("28 7 9 18 12 12 7 7 8 7 7 8 10 10", w, " ")
		else split("28 9 12 11 12 11 10 9 10 9 11 10 11 10", w, " ")
		s = ""
		for (i = 1; i < NF; i++) s = s sprintf("%-" w[i] "s ", $i)
		print s $NF }'
}

# solve OUT.tsv ERR LABEL FILE OPTS...: one bounded gfmd-solve run.  Sets
# S_STATUS (exit status, 124 = stopped by a bound), S_BOUND (which),
# S_WALL (its wall seconds) and writes the rows done.
solve() {
	out=$1 err=$2 f=$4
	shift 4
	t0=$(date +%s)
	if [ "$TKIND" = s ]; then
		timeout "$TLIM" "$RC_BIN/gfmd-solve" $SOLVE_OPTS "$@" -p "$PRESSURES" "$f" >"$out" 2>"$err"
		S_STATUS=$?
		S_WALL=$(($(date +%s) - t0)) S_BOUND="$TLIM s"
		return
	fi
	timeout $((10 * TLIM)) "$RC_BIN/gfmd-solve" $SOLVE_OPTS "$@" -p "$PRESSURES" "$f" >"$out" 2>"$err" &
	tpid=$!
	# the solver is timeout's child: its CPU time (fields 14, 15 of stat)
	cpid="" stopped=0
	while kill -0 "$tpid" 2>/dev/null; do
		[ -n "$cpid" ] || cpid=$(pgrep -P "$tpid" 2>/dev/null | head -n 1)
		if [ -n "$cpid" ] && [ -r "/proc/$cpid/stat" ]; then
			cpu=$(sed 's/.*) //' "/proc/$cpid/stat" 2>/dev/null | awk -v c="$CLK" '{ printf "%d", ($12 + $13) / c }')
			if [ "${cpu:-0}" -ge "$TLIM" ]; then
				kill -TERM "$cpid" 2>/dev/null
				stopped=1
				break
			fi
		fi
		sleep 0.2
	done
	wait "$tpid"
	S_STATUS=$?
	S_WALL=$(($(date +%s) - t0)) S_BOUND="$((10 * TLIM)) wall s"
	[ "$stopped" = 1 ] && S_STATUS=124 S_BOUND="$TLIM CPU s"
}
# per_pressure OUT ERR K: PP_IT, PP_S, PP_A of the K-th pressure (PP_IT
# with '*' when not converged, '-' when not reached) and a note in P_NOTE
per_pressure() {
	out=$1 err=$2 k=$3
	P_NOTE=""
	pk=$(echo "$PRESSURES" | cut -d, -f"$k")
	if [ -s "$out" ] && [ "$(awk 'END { print NR }' "$out")" -gt "$k" ]; then
		it=$(col "$out" iterations "$k") res=$(col "$out" residual "$k") tol=$(col "$out" tol "$k")
		s=$(secs "$(col "$out" seconds "$k")") a=$(sig "$(col "$out" a_r "$k")")
		if awk -v r="$res" -v t="$tol" 'BEGIN { exit !(r + 0 <= t + 0) }'; then
			PP_IT=$it PP_S=$s PP_A=$a
		else
			P_NOTE="p*=$pk: not converged after $it it. (residual $(sig "$res"))"
			PP_IT="$it*" PP_S=$s PP_A=$a
		fi
	elif [ "$(awk 'END { print (NR > 1 ? NR : 1) }' "$out" 2>/dev/null)" -lt "$k" ] && [ "$S_STATUS" = 124 ]; then
		P_NOTE="p*=$pk: not reached (the time bound, $S_BOUND, stopped an earlier pressure)"
		PP_IT=- PP_S=- PP_A=-
	elif [ "$S_STATUS" = 124 ]; then
		# gfmd-solve says at which iteration the signal stopped it
		it=$(sed -n 's/.*while solving p = [^ ]* (iteration \([0-9]*\)).*/\1/p' "$err" | head -n 1)
		done_s=$(awk -F '\t' 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "seconds") a = i; if ($i == "plan_seconds") b = i }; next }
			{ s += $a; p = $b } END { printf "%.0f", s + p }' "$out" 2>/dev/null)
		P_NOTE="p*=$pk: stopped by the time bound ($S_BOUND)"
		PP_IT="${it:-?}*" PP_S=">$((S_WALL - ${done_s:-0}))" PP_A=-
	else
		P_NOTE="p*=$pk: $(msg "$err" "")"
		PP_IT=- PP_S=- PP_A=-
	fi
}

# secs X: seconds to 3 digits, "<0.01" below
secs() { awk -v x="$1" 'BEGIN { if (x + 0 < 0.01) print "<0.01"; else printf "%.3g\n", x }'; }

# units of the tools' tables, in metres ("-" = none: 1)
to_m() { awk -v x="$1" -v u="$2" 'BEGIN { f["m"] = 1; f["mm"] = 1e-3; f["um"] = 1e-6; f["µm"] = 1e-6
	f["nm"] = 1e-9; f["pm"] = 1e-12; f["angstrom"] = 1e-10; f["Å"] = 1e-10; f["-"] = 1; f[""] = 1
	if (!(u in f)) { print "nan"; exit } printf "%.17g\n", x * f[u] }'; }

# read_check FILE BASE: sets R_READ (right, wrong(..), unchecked, refused),
# R_NOTE, R_NX, R_NY; 0 if the heights could be read
read_check() {
	f=$1 base=$2
	R_NOTE="" R_NX="" R_NY=""
	if ! timeout $STEP_TLIM "$RC_BIN/surfstat" --channels "$f" >"$TMP/ch.tsv" 2>"$TMP/ch.err"; then
		R_READ=refused R_NOTE=$(msg "$TMP/ch.err" "$base")
		return 1
	fi
	if ! timeout $STEP_TLIM "$RC_BIN/surfstat" -q --iso "$f" >"$TMP/raw.tsv" 2>"$TMP/raw.err"; then
		# a line scan not uniformly spaced has no --iso: surfstat's
		# scalar row of it as it is (piecewise linear) says it is read
		if grep -q "not uniformly spaced is analysed as it is" "$TMP/raw.err" &&
		    timeout $STEP_TLIM "$RC_BIN/surfstat" -q "$f" >"$TMP/nu.tsv" 2>"$TMP/raw.err"; then
			R_NX=$(col "$TMP/nu.tsv" nx) R_NY=$(col "$TMP/nu.tsv" ny) R_READ=unchecked
			R_NOTE="not uniformly spaced, read as it is: lx $(col "$TMP/nu.tsv" lx), hrms $(col "$TMP/nu.tsv" hrms), rms_slope $(col "$TMP/nu.tsv" rms_slope) ($(col "$TMP/nu.tsv" unit))"
			return 0
		fi
		R_READ=refused R_NOTE=$(msg "$TMP/raw.err" "$base")
		return 1
	fi
	# the default channel: the first whose values are lengths
	awk -F '\t' 'NR > 1 && $8 ~ /^(m|mm|um|µm|nm|pm|angstrom|Å|-)$/ { print; exit }' "$TMP/ch.tsv" >"$TMP/ch.row"
	c_no=$(cut -f1 "$TMP/ch.row") c_title=$(cut -f2 "$TMP/ch.row") c_lx=$(cut -f5 "$TMP/ch.row")
	c_ly=$(cut -f6 "$TMP/ch.row") c_unit=$(cut -f7 "$TMP/ch.row")
	R_NX=$(col "$TMP/raw.tsv" nx) R_NY=$(col "$TMP/raw.tsv" ny)
	sq=$(col "$TMP/raw.tsv" Sq)
	R_READ=unchecked
	[ -n "$MANIFEST" ] || return 0
	awk -F '\t' -v f="$base" -v no="$c_no" -v t="$c_title" '
		$1 == f && $2 == "yes" { if ($4 == t && !bt) bt = $0; if ($3 == no) bn = $0 }
		END { if (bt != "") print bt; else if (bn != "") print bn }' "$MANIFEST" >"$TMP/man.row"
	[ -s "$TMP/man.row" ] || return 0
	# (empty fields, e.g. a unitless xyz file's units, become "-")
	mf() { awk -F '\t' -v i="$1" '{ print ($i == "" ? "-" : $i) }' "$TMP/man.row"; }
	m_no=$(mf 3) m_nx=$(mf 5) m_ny=$(mf 6) m_lx=$(mf 7) m_ly=$(mf 8) m_xyu=$(mf 9) m_zu=$(mf 10) m_rms=$(mf 12)
	bad=""
	[ "$R_NX" = "$m_nx" ] || bad="$bad,nx"
	[ "$R_NY" = "$m_ny" ] || bad="$bad,ny"
	rel() { awk -v a="$1" -v b="$2" 'BEGIN { if (a ~ /nan/ || b ~ /nan/ || a == "" || b == "") exit 1
		s = b < 0 ? -b : b; d = a - b; if (d < 0) d = -d; exit !(d <= 1e-6 * s) }'; }
	rel "$(to_m "$c_lx" "$c_unit")" "$(to_m "$m_lx" "$m_xyu")" || bad="$bad,lx"
	rel "$(to_m "$c_ly" "$c_unit")" "$(to_m "$m_ly" "$m_xyu")" || bad="$bad,ly"
	# unit: both length units (or both none); the scale is in lx and rms
	case "$c_unit:$m_xyu" in -:-|[a-zµÅ]*:[a-zµ]*) ;; *) bad="$bad,unit" ;; esac
	# rms: ours is in the lateral unit (heights brought to it)
	# (Gwyddion gives nan where a file marks missing points as NaN
	# without a mask: no reference then)
	case $m_rms in
	*nan*) R_NOTE="rms not compared (manifest: $m_rms)" ;;
	*) rel "$(to_m "$sq" "$c_unit")" "$(to_m "$m_rms" "$m_zu")" || bad="$bad,rms" ;;
	esac
	if [ -z "$bad" ]; then R_READ=right; else R_READ="wrong(${bad#,})"
		R_NOTE="manifest channel $m_no: $m_nx x $m_ny, $m_lx x $m_ly $m_xyu, rms $m_rms $m_zu; read $R_NX x $R_NY, $c_lx x $c_ly $c_unit, Sq $sq"
	fi
	return 0
}

# fit_verdict LEV: "H=0.83" if surfstat --fit gives 0 < H < 1 with a
# finite error, "H=2.4(out)" if not, "failed" (note: its message)
fit_verdict() {
	if ! timeout $STEP_TLIM "$RC_BIN/surfstat" -q --fit "$1" >"$TMP/fit.tsv" 2>"$TMP/fit.err"; then
		echo failed
		return
	fi
	awk -v h="$(col "$TMP/fit.tsv" H)" -v e="$(col "$TMP/fit.tsv" H_err)" 'BEGIN {
		ok = (h + 0 == h && h > 0 && h < 1 && e + 0 == e)
		printf "H=%.2g%s\n", h, ok ? "" : "(out)" }'
}

N_REF_GWY=0 N_FILES=0 N_READ=0 N_RIGHT=0 N_WRONG=0 N_UNCHK=0 N_REFUSED=0 N_CONV=0 N_NOCONV=0 N_NOSOLVE=0
if [ "$MODE" = path ]; then
	echo "# field.sh: $(cd "$DIR" && pwd), manifest ${MANIFEST:-none}, tools $RC_BIN, $BOUND, -j $THREADS"
	echo "# it: iterations (* not converged: see note); s: solve seconds; a_ext: a_r of the map and its 2x coarser copy through contact-stats"
	[ -r /proc/loadavg ] && echo "# load average $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc 2>/dev/null || echo ?) cores"
	emit "$HEAD_PATH"
else
	echo "# field.sh --solvers: $(cd "$DIR" && pwd), tools $RC_BIN, $BOUND, -j $THREADS; levelled maps (surfwarp --detrend plane --fill)"
	echo "# fire, cg: free boundaries; per: periodic FIRE on the same grid; it * = not converged"
	[ -r /proc/loadavg ] && echo "# load average $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc 2>/dev/null || echo ?) cores"
	emit "$HEAD_SOLV"
fi

for f in "$DIR"/*; do
	[ -f "$f" ] || continue
	base=${f##*/}
	case $base in MANIFEST.tsv|README*) continue ;; esac
	N_FILES=$((N_FILES + 1))
	fmt=$(echo "$base" | sed -n 's/^[^.]*\.//p' | tr 'A-Z' 'a-z')
	rm -f "$TMP"/*
	if ! read_check "$f" "$base"; then
		N_REFUSED=$((N_REFUSED + 1))
		if [ -n "$MANIFEST" ] && awk -F '\t' -v f="$base" '$1 == f && $2 == "yes" { y = 1 } END { exit !y }' "$MANIFEST"; then
			N_REF_GWY=$((N_REF_GWY + 1))
			R_NOTE="$R_NOTE (Gwyddion reads it)"
		fi
		if [ "$MODE" = path ]; then
			emit "$base	${fmt:--}	-	refused	-	-	-	-	-	-	-	-	-	-	$R_NOTE"
		else
			emit "$base	-	-	-	-	-	-	-	-	-	-	-	-	-	refused: $R_NOTE"
		fi
		continue
	fi
	N_READ=$((N_READ + 1))
	case $R_READ in right) N_RIGHT=$((N_RIGHT + 1)) ;; wrong*) N_WRONG=$((N_WRONG + 1)) ;; *) N_UNCHK=$((N_UNCHK + 1)) ;; esac
	grid="${R_NX}x$R_NY"
	note=$R_NOTE
	add() { [ -n "$1" ] && note="${note:+$note; }$1"; return 0; }
	lev=$TMP/lev.surf
	if ! timeout $STEP_TLIM "$RC_BIN/surfwarp" -q --detrend plane --fill -o "$lev" "$f" 2>"$TMP/lev.err"; then
		add "level: $(msg "$TMP/lev.err" "$base")"
		N_NOSOLVE=$((N_NOSOLVE + 1))
		if [ "$MODE" = path ]; then
			emit "$base	${fmt:--}	$grid	$R_READ	-	-	-	-	-	-	-	-	-	-	$note"
		else
			emit "$base	$grid	-	-	-	-	-	-	-	-	-	-	-	-	$note"
		fi
		continue
	fi

	if [ "$MODE" = solvers ]; then
		row="$base	$grid"
		for v in "fire --boundary free" "cg --boundary free --method cg" "per --boundary periodic"; do
			set -- $v
			lbl=$1
			shift
			solve "$TMP/$lbl.tsv" "$TMP/$lbl.err" "$lbl" "$lev" "$@"
			for k in 1 2; do
				per_pressure "$TMP/$lbl.tsv" "$TMP/$lbl.err" "$k"
				row="$row	$PP_IT	$PP_S"
				[ -n "$P_NOTE" ] && add "$lbl $P_NOTE"
			done
		done
		emit "$row	${note:--}"
		continue
	fi

	sq_lev=-
	if timeout $STEP_TLIM "$RC_BIN/surfstat" -q --iso "$lev" >"$TMP/lev-iso.tsv" 2>"$TMP/lev-iso.err"; then
		timeout $STEP_TLIM "$RC_BIN/surfstat" --channels "$lev" >"$TMP/lev-ch.tsv" 2>/dev/null
		u=$(col "$TMP/lev-ch.tsv" unit)
		sq_lev="$(sig "$(col "$TMP/lev-iso.tsv" Sq)")${u#-}"
	else
		add "iso: $(msg "$TMP/lev-iso.err" "")"
	fi
	fit=$(fit_verdict "$lev")
	[ "$fit" = failed ] && add "fit: $(msg "$TMP/fit.err" "")"
	solve "$TMP/fine.tsv" "$TMP/fine.err" fine "$lev"
	nf=$(col "$TMP/fine.tsv" filled_points)
	case $nf in ""|0) ;; *) add "$nf of $((R_NX * R_NY)) points filled" ;; esac
	conv=yes
	cells="" last=""
	for k in 1 2; do
		per_pressure "$TMP/fine.tsv" "$TMP/fine.err" "$k"
		cells="$cells	$PP_IT	$PP_S	$PP_A"
		case $PP_IT in *\*) conv=no ;; -) [ "$conv" = yes ] && conv=refused ;; esac
		# a message both pressures share is said once
		if [ -n "$last" ] && [ "${P_NOTE#p\*=*: }" = "${last#p\*=*: }" ]; then
			note=$(printf '%s' "$note" | sed "s|p\*=0.01: |p*=$PRESSURES: |")
		else
			add "$P_NOTE"
		fi
		last=$P_NOTE
	done
	case $conv in yes) N_CONV=$((N_CONV + 1)) ;; no) N_NOCONV=$((N_NOCONV + 1)) ;; *) N_NOSOLVE=$((N_NOSOLVE + 1)) ;; esac
	ext="-	-"
	if [ "$conv" != yes ]; then
		:
	elif [ "$R_NX" -lt $MIN_COARSE ] || [ "$R_NY" -lt $MIN_COARSE ]; then
		add "one grid only (under $MIN_COARSE points a side)"
	else
		# Two grids of one patch: an odd side cannot be halved (the coarse
		# copy would be a patch of another size, so contact-stats would see
		# two systems), so the pair is the map cropped to even sides.
		pair=$lev pair_rows=$TMP/fine.tsv
		if [ $((R_NX % 2)) = 1 ] || [ $((R_NY % 2)) = 1 ]; then
			pair=$TMP/even.surf pair_rows=$TMP/even.tsv
			timeout $STEP_TLIM "$RC_BIN/surfwarp" -q --crop "0:$((R_NX / 2 * 2)),0:$((R_NY / 2 * 2))" \
			    -o "$pair" "$lev" 2>"$TMP/even.err" &&
			    solve "$pair_rows" "$TMP/even-s.err" even "$pair"
			add "pair on the map cropped to $((R_NX / 2 * 2))x$((R_NY / 2 * 2))"
		fi
		d=$(awk -F '\t' 'NR == 2 { printf "%.17gx%.17g", 2 * $5 / $3, 2 * $6 / $4 }' "$TMP/lev-ch.tsv")
		if ! timeout $STEP_TLIM "$RC_BIN/surfwarp" -q --resample "$d" -o "$TMP/coarse.surf" "$pair" 2>"$TMP/coarse.err"; then
			add "coarsen: $(msg "$TMP/coarse.err" "")"
		else
			solve "$TMP/coarse.tsv" "$TMP/coarse-s.err" coarse "$TMP/coarse.surf"
			if [ "$S_STATUS" = 124 ]; then
				add "coarse solve stopped by the time bound ($S_BOUND)"
			elif timeout $STEP_TLIM "$RC_BIN/contact-stats" -q "$pair_rows" "$TMP/coarse.tsv" >"$TMP/cs.tsv" 2>"$TMP/cs.err"; then
				ext="$(sig "$(col "$TMP/cs.tsv" a_r 1)")	$(sig "$(col "$TMP/cs.tsv" a_r 2)")"
			else
				add "contact-stats: $(msg "$TMP/cs.err" "")"
			fi
		fi
	fi
	emit "$base	${fmt:--}	$grid	$R_READ	$sq_lev	$fit$cells	$ext	${note:--}"
done

if [ "$MODE" = path ]; then
	echo "# files $N_FILES: read $N_READ (right $N_RIGHT, wrong $N_WRONG, unchecked $N_UNCHK), refused $N_REFUSED${MANIFEST:+ ($N_REF_GWY of them read by Gwyddion)}; solved: converged $N_CONV, not converged $N_NOCONV, not solved $N_NOSOLVE ($BOUND)"
else
	echo "# files $N_FILES: read $N_READ, refused $N_REFUSED, not levelled $N_NOSOLVE ($BOUND)"
fi
exit 0
