#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# checkpoint.sh - gfmd-solve --checkpoint / --checkpoint-every / --resume:
# an interrupted sweep, resumed with the command its message prints,
# gives the rows of an uninterrupted run.
. "$RC_TOP/tests/e2e/lib.sh"
T=$T_TMP
cd "$T" || exit 1

PLIST=0.005,0.01,0.02,0.03,0.05,0.08,0.12,0.2
TOL=1e-9

# same_rows REF GOT: the same pressures (bit for bit), n_c within one
# point (a contact point whose pressure is within the tolerance of zero
# may flip on another path to the same fixed point), the elastic energy
# to 1e-6 relative (the energy error is second order in the residual,
# 1e-9 here; 1e-6 leaves a wide margin yet catches a wrong state).
same_rows() {
	paste "$1" "$2" | awk -F'\t' '
	NR == 1 { h = NF / 2; for (i = 1; i <= h; i++) c[$i] = i
		if ($1 != $(h + 1) || NF % 2) { print "headers differ"; bad++ } next }
	{ rows++
	  if ($c["p"] != $(c["p"] + h)) { print "row " NR - 1 ": p " $c["p"] " vs " $(c["p"] + h); bad++ }
	  d = $c["n_c"] - $(c["n_c"] + h); if (d < 0) d = -d
	  if (d > 1) { print "row " NR - 1 ": n_c " $c["n_c"] " vs " $(c["n_c"] + h); bad++ }
	  e = $c["elastic_energy"]; f = $(c["elastic_energy"] + h); r = (e - f) / e; if (r < 0) r = -r
	  if (r > 1e-6) { print "row " NR - 1 ": energy " e " vs " f; bad++ } }
	END { if (rows != 8) { print rows + 0 " rows"; bad++ } exit bad > 0 }'
}

# --- The uninterrupted reference.
n=256
surfgen -n $n --seed 5 --lambda-s 0.02 -o s$n.surf
gfmd-solve -j 1 -q --tol $TOL -p $PLIST -o ref$n.tsv s$n.surf
check "reference run" test $? -eq 0

# --- Interrupt a run once its first checkpoint exists (so the handlers
# are installed and a pressure is done), resume it with the printed
# command.  If the run finishes first (a fast machine), try a grid twice
# as fine, and assert the finished run's rows on the way.
interrupted=0
for n in 256 512 1024; do
	if [ ! -f s$n.surf ]; then
		surfgen -n $n --seed 5 --lambda-s 0.02 -o s$n.surf
		gfmd-solve -j 1 -q --tol $TOL -p $PLIST -o ref$n.tsv s$n.surf
	fi
	rm -f ck.surf part.tsv
	gfmd-solve -j 1 -q --tol $TOL -p $PLIST --checkpoint ck.surf -o part.tsv \
	    s$n.surf 2>msg &
	pid=$!
	i=0
	while [ ! -f ck.surf ] && [ $i -lt 300 ] && kill -0 $pid 2>/dev/null; do
		sleep 0.05; i=$((i + 1))
	done
	kill -INT $pid 2>/dev/null
	wait $pid
	st=$?
	if [ $st -eq 0 ]; then
		# Finished before the signal: complete rows, checkpoint gone.
		same_rows ref$n.tsv part.tsv > cmp
		check "n = $n finished before the signal: rows as the reference ($(head -n 2 cmp))" test $? -eq 0
		check "n = $n finished: checkpoint removed" test ! -f ck.surf
		continue
	fi
	interrupted=1
	check_rel "interrupted: exit status 1" $st 1 0
	grep -q 'interrupted by signal 2' msg
	check "interrupted: the message names the signal ($(head -c 200 msg))" test $? -eq 0
	grep -q 'state saved in ck.surf; resume with: gfmd-solve -j 1 -q --tol 1e-9 -p [0-9.,]* --checkpoint ck.surf -o part.tsv s'$n'.surf --resume ck.surf$' msg
	check "interrupted: the message gives the resume command" test $? -eq 0
	check "interrupted: checkpoint written" test -f ck.surf
	head -c 2000 ck.surf | grep -q '^meta.checkpoint.pressures = 0.005,0.01,0.02,0.03,0.05,0.08,0.12,0.2$'
	check "checkpoint holds the full pressure list" test $? -eq 0
	done_rows=$(($(wc -l < part.tsv) - 1))
	next=$(head -c 4000 ck.surf | sed -n 's/^meta.checkpoint.next = //p')
	check_range "interrupted: some but not all rows in -o" $done_rows 1 7
	check_rel "checkpoint's next pressure = rows written" "$next" $done_rows 0
	# Resume exactly as told.
	cmd=$(sed -n 's/.*resume with: //p' msg)
	sh -c "$cmd" 2>resume.err
	check_rel "resume: exit 0 ($(head -c 200 resume.err))" $? 0 0
	same_rows ref$n.tsv part.tsv > cmp
	check "resumed run = uninterrupted run ($(head -n 3 cmp | tr '\n' ' '))" test $? -eq 0
	check "resume complete: checkpoint removed" test ! -f ck.surf
	break
done
check "SIGINT landed between pressures (grids up to 1024^2), so the resume path ran" \
    test $interrupted -eq 1

# --- SIGTERM mid-solve: without --checkpoint the message says how to get
# one.  Taught: FIRE solves 256^2 to 1e-9 in less than the 0.3 s this
# waited, so the check silently never ran; and on a loaded machine the
# signal came before the solve began (reading, planning), which kills the
# tool outright (143).  So the solve is made endless (a tolerance of 1e-15
# that 512^2 never reaches in a million iterations) and the wait grows
# until the signal lands inside it.
terminated=0
[ -f s512.surf ] || surfgen -n 512 --seed 5 --lambda-s 0.02 -o s512.surf
for wait_s in 0.5 1 2 4 8; do
	gfmd-solve -j 1 -q --tol 1e-15 --stall 0 --max-iter 1000000 -p 0.01 s512.surf > noref.tsv 2>msg &
	pid=$!
	sleep $wait_s
	kill -TERM $pid 2>/dev/null
	wait $pid
	st=$?
	[ $st -eq 143 ] && continue
	terminated=1
	check_rel "SIGTERM mid-solve: exit status 1" $st 1 0
	grep -q 'interrupted by signal 15' msg
	check "SIGTERM: the message names the signal ($(head -c 200 msg))" test $? -eq 0
	grep -q -- '--checkpoint FILE makes a run resumable' msg
	check "no --checkpoint: the message says how to make it resumable" test $? -eq 0
	break
done
check "SIGTERM landed inside a solve (waits up to 8 s)" test $terminated -eq 1

# --- Periodic checkpoints (every 0.005 min = 0.3 s, several per run)
# stop and continue solves; the rows still equal the reference, and the
# file is gone at the end.  Taught: an interval shorter than a solve's
# restart cost (30 ms tried first) restarts FIRE's momentum so often
# that a loaded or sanitized run never converges; gfmd-solve(1) says so.
rm -f ck2.surf
gfmd-solve -j 1 -q --tol $TOL -p $PLIST --checkpoint ck2.surf \
    --checkpoint-every 0.005 s256.surf > every.tsv
check "--checkpoint-every: exit 0" test $? -eq 0
same_rows ref256.tsv every.tsv > cmp
check "--checkpoint-every: rows as the reference ($(head -n 2 cmp | tr '\n' ' '))" test $? -eq 0
check "--checkpoint-every: checkpoint removed at the end" test ! -f ck2.surf

# --- A checkpoint saved mid-solve with --max-iter small enough: resume
# it by hand and check every mismatch is refused with its reason.
gfmd-solve -j 1 -q --tol $TOL -p $PLIST --checkpoint ck3.surf s256.surf > /dev/null 2>msg &
pid=$!
i=0
while [ ! -f ck3.surf ] && [ $i -lt 300 ] && kill -0 $pid 2>/dev/null; do sleep 0.05; i=$((i + 1)); done
kill -INT $pid 2>/dev/null; wait $pid
if [ -f ck3.surf ]; then
	# An unfinished run's checkpoint at --checkpoint of a new run (not
	# --resume): it was replaced, then removed at the end; refused now.
	cp ck3.surf ck3.keep
	check_status "--checkpoint on an unfinished run's checkpoint: exit 2" 2 \
	    gfmd-solve -q -p 0.05 --checkpoint ck3.surf -o other.tsv s256.surf
	check "  says how to continue it" grep -q \
	    'ck3.surf: the file holds the saved state of an unfinished run (.*continue it with --resume ck3.surf' \
	    "$T_TMP/stderr"
	check "  the checkpoint is kept" cmp -s ck3.surf ck3.keep
	check "  no rows written" test ! -e other.tsv
	gfmd-solve -q --tol 1e-8 --resume ck3.surf s256.surf > /dev/null 2>err
	check_rel "resume with another --tol: exit 1" $? 1 0
	check "resume with another --tol: named" grep -q 'checkpoint has --tol' err
	gfmd-solve -q --method cg --resume ck3.surf s256.surf > /dev/null 2>err
	check "resume with another method: named" grep -q 'checkpoint has --method fire, this run cg' err
	gfmd-solve -q -p 0.01 --resume ck3.surf s256.surf > /dev/null 2>err
	check "resume with another pressure list: named" grep -q 'checkpoint has 8 pressures, this run 1' err
	check_status "resume of a non-adhesive checkpoint with --law: exit 2" 2 \
	    gfmd-solve -q --law dugdale --resume ck3.surf s256.surf
	check "resume of a non-adhesive checkpoint with --law: says it has no adhesion" \
	    grep -q 'has no adhesion to give a law to' "$T_TMP/stderr"
	surfgen -n 256 --seed 6 --lambda-s 0.02 -o other.surf
	gfmd-solve -q --resume ck3.surf other.surf > /dev/null 2>err
	check "resume on another indenter: named" grep -q 'another indenter' err
	check_status "resume on another grid size: exit 1" 1 gfmd-solve -q --resume ck3.surf s512.surf
	# Options not given come from the checkpoint: same rows.
	gfmd-solve -j 1 -q --resume ck3.surf s256.surf > byhand.tsv
	same_rows ref256.tsv byhand.tsv > cmp
	check "resume with the options from the checkpoint ($(head -n 2 cmp | tr '\n' ' '))" test $? -eq 0
	check "resume without --checkpoint keeps the file" test -f ck3.surf
fi

# --- The scene is recorded (checkpoint version 3): a sphere on a
# periodic map solved with --boundary free and adhesion, loads going
# down past zero.  The checkpoint saved after a pressure is copied while
# the run goes on; resumed from the copy without any option, the run
# takes the boundary kind and the adhesion from it: its rows equal the
# uninterrupted ones (n_c within a point, the energy to 1e-6 as above).
# A bigger grid is tried if the run ended before the copy was made.
SC="--boundary free --adhesion 0.25 --range 0.5 --tol 1e-8"
SP=0.004,0.002,0,-0.002,-0.003
copied=0
for n in 128 256; do
	surfgen -q -n $n -L $n --type harmonic --radius $((n / 2)) -o sph$n.surf
	# shellcheck disable=SC2086
	gfmd-solve -j 1 -q $SC --pressure-abs $SP -o sref.tsv sph$n.surf
	rm -f sck.surf scopy.surf
	# shellcheck disable=SC2086
	gfmd-solve -j 1 -q $SC --pressure-abs $SP --checkpoint sck.surf \
	    -o spart.tsv sph$n.surf & pid=$!
	while kill -0 $pid 2>/dev/null && [ ! -s scopy.surf ]; do
		cp sck.surf scopy.surf 2>/dev/null
		sleep 0.02
	done
	wait $pid
	[ -s scopy.surf ] && { copied=1; break; }
done
if [ $copied = 1 ]; then
	check "scene: the checkpoint records free boundaries" \
	    grep -a -q '^meta.checkpoint.boundary = free$' scopy.surf
	check "scene: and the adhesion" grep -a -q '^meta.checkpoint.adhesion = 0.25$' scopy.surf
	gfmd-solve -j 1 -q --resume scopy.surf sph$n.surf > sres.tsv 2>err
	check_rel "scene: resumed with no option: exit 0 ($(head -c 150 err))" $? 0 0
	paste sref.tsv sres.tsv | awk -F'\t' '
	NR == 1 { h = NF / 2; for (i = 1; i <= h; i++) c[$i] = i; next }
	{ rows++
	  if ($c["p"] != $(c["p"] + h)) bad++
	  if ($(c["boundary"] + h) != "free" || $(c["adhesion"] + h) != 0.25) bad++
	  d = $c["n_c"] - $(c["n_c"] + h); if (d < 0) d = -d; if (d > 1) bad++
	  e = $c["elastic_energy"]; f = $(c["elastic_energy"] + h); r = (e - f) / e
	  if (r < 0) r = -r; if (r > 1e-6) bad++ }
	END { exit !(rows == 5 && bad == 0) }'
	check "scene: resumed rows = uninterrupted rows (free, adhesive)" test $? -eq 0
	gfmd-solve -q --boundary periodic --resume scopy.surf sph$n.surf > /dev/null 2>err
	check "scene: resume with another boundary: named ($(head -c 150 err))" \
	    grep -q 'checkpoint has --boundary free, this run periodic' err
	gfmd-solve -q --adhesion 0.2 --range 0.5 --resume scopy.surf sph$n.surf > /dev/null 2>err
	check "scene: resume with another adhesion: named ($(head -c 150 err))" \
	    grep -q 'checkpoint has --adhesion 0.25' err
	check "scene: and the law (checkpoint version 4)" \
	    grep -a -q '^meta.checkpoint.law = exponential$' scopy.surf
	gfmd-solve -q --law dugdale --resume scopy.surf sph$n.surf > /dev/null 2>err
	check "scene: resume with another law: named ($(head -c 150 err))" \
	    grep -q 'checkpoint has --law exponential, this run dugdale' err
else
	skip 8 "scene: every run ended before its checkpoint could be copied"
fi
# The effects take checkpoints now (refused while the scene was not
# recorded): a plastic sweep with one gives the rows of one without.
gfmd-solve -j 1 -q --method cg --hardness 0.5 -p 0.05,0.1 -o h1.tsv s256.surf
gfmd-solve -j 1 -q --method cg --hardness 0.5 -p 0.05,0.1 --checkpoint hck.surf \
    -o h2.tsv s256.surf
check "--hardness with --checkpoint: accepted, the same rows" \
    test "$(cut -f 1-20 h1.tsv)" = "$(cut -f 1-20 h2.tsv)"

# --- Usage and bad checkpoints.
check_status "--checkpoint-every without --checkpoint: exit 2" 2 gfmd-solve -p 0.1 --checkpoint-every 1 s256.surf
check_status "--checkpoint-every 0: exit 2" 2 gfmd-solve -p 0.1 --checkpoint x.surf --checkpoint-every 0 s256.surf
check_status "--checkpoint-every below 0.005 min: exit 2" 2 gfmd-solve -p 0.1 --checkpoint x.surf --checkpoint-every 0.004 s256.surf
check_status "--resume with --init: exit 2" 2 gfmd-solve --resume ck3.surf --init s256.surf s256.surf
check_status "--checkpoint -: exit 2" 2 gfmd-solve -p 0.1 --checkpoint - s256.surf
gfmd-solve -q --resume s256.surf s256.surf > /dev/null 2>err
check_rel "a plain surface as checkpoint: exit 1" $? 1 0
check "a plain surface as checkpoint: named" grep -q 'not a gfmd-solve checkpoint' err
check_status "a missing checkpoint: exit 1" 1 gfmd-solve -q --resume nothere.surf s256.surf
# --- The identity covers metadata: the same heights and cell without the
# metadata (a bare .txt copy) would give rows with other columns, so resuming
# on them is refused before any work (it used to solve, then fail with
# "internal: row has N columns").
if [ -f ck3.surf ]; then
	surfwarp -o plain.txt s256.surf
	grep -v '^#' plain.txt > bare.txt
	gfmd-solve -q -L 1 --resume ck3.surf bare.txt > /dev/null 2>err
	check_rel "resume on the same heights without metadata: exit 1" $? 1 0
	check "  named as another indenter" grep -q 'another indenter' err
	# Values read back are range-checked: each made negative (same
	# length, so the header's data offset stays right).
	for key in tol E alpha max_iter iterations next; do
		perl -pe 's/^(meta\.checkpoint\.'$key' = )(.*)$/$1 . "-" . ("9" x (length($2) - 1))/e if /^meta\.checkpoint\.'$key' = /' \
		    ck3.surf > bad.surf
		cmp -s bad.surf ck3.surf && { fail "bad $key: the edit did nothing"; continue; }
		gfmd-solve -q --resume bad.surf s256.surf > /dev/null 2>err
		check_rel "checkpoint with $key out of range: exit 1 ($(head -c 150 err))" $? 1 0
	done
	perl -pe 's/^meta\.checkpoint\.method = fire$/meta.checkpoint.method = fira/' ck3.surf > bad.surf
	gfmd-solve -q --resume bad.surf s256.surf > /dev/null 2>err
	check "checkpoint with an unknown method: refused" grep -q 'method = fira: unknown' err
	# Issue 27: an edited a_r in a finished row came out as a result
	# (exit 0); the checkpoint's sum refuses it.  The last digit of row 0
	# changed (same length, the data offset stays).
	perl -pe 's/(\d)$/($1 + 1) % 10/e if /^meta\.checkpoint\.row\.0 = /' \
	    ck3.surf > bad.surf
	if cmp -s bad.surf ck3.surf; then fail "edited row: the edit did nothing"; else
		gfmd-solve -q --resume bad.surf s256.surf > /dev/null 2>err
		check_rel "checkpoint with an edited row: exit 1" $? 1 0
		check "  the sum names it ($(head -c 150 err))" grep -q 'checkpoint.sum' err
	fi
fi

# --- One run per checkpoint: a second run on the same --checkpoint is
# refused while the first holds its lock; a lock file left by a killed run
# does not block the next one.
rm -f lk.surf .lk.surf.lock
gfmd-solve -j 1 -q --tol 1e-15 --stall 0 --max-iter 1000000 -p 0.01,0.02 --checkpoint lk.surf \
    s512.surf > /dev/null 2>&1 & pid=$!
i=0
while [ ! -f .lk.surf.lock ] && [ $i -lt 400 ]; do sleep 0.05; i=$((i + 1)); done
gfmd-solve -q -p 0.01 --checkpoint lk.surf s256.surf > /dev/null 2>err; st=$?
kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null
check_rel "a second run on a checkpoint in use: exit 1" $st 1 0
check "  said so ($(head -c 150 err))" grep -q 'another run is using this checkpoint' err
check "  the killed run left its lock file" test -f .lk.surf.lock
gfmd-solve -q -p 0.01 --checkpoint lk.surf -o lk.tsv s256.surf 2>err
check_rel "a stale lock file does not block ($(head -c 150 err))" $? 0 0
check "  and is removed at the end" test ! -f .lk.surf.lock

# --- A checkpoint that cannot be written (a full disk: /dev/full, or a
# private node of it as root): the first pressure's save fails with a
# warning and the run goes on; SIGINT in the second solve keeps the
# finished row (as gfmd-solve(1) promises), exit 1, saying why.
if mknod full c 1 7 2>/dev/null; then FULLDEV=$PWD/full; else FULLDEV=/dev/full; fi
surfgen -n 128 --seed 5 -o s128.surf
gfmd-solve -j 1 --tol 1e-15 --stall 0 --max-iter 3000 -p 0.01,0.02 --checkpoint "$FULLDEV" \
    -o full.tsv s128.surf 2>fullmsg & pid=$!
i=0
while ! grep -q 'going on' fullmsg && [ $i -lt 600 ] && kill -0 $pid 2>/dev/null; do
	sleep 0.05; i=$((i + 1))
done
kill -INT $pid 2>/dev/null; killed=$?
wait $pid; st=$?
if [ $killed = 0 ] && grep -q 'going on' fullmsg; then
	check_rel "interrupted with an unwritable checkpoint: exit 1" $st 1 0
	check "  the message says why ($(tail -n 1 fullmsg | head -c 200))" grep -q 'could not be written' fullmsg
	check "  the finished row is kept" test "$(awk 'END { print NR }' full.tsv 2>/dev/null)" = 2
	check "  the device is still a device" test "$(stat -c %F "$FULLDEV")" = "character special file"
else
	skip 4 "unwritable checkpoint: the run ended before the signal (exit $st)"
fi
# --- Issue 27: --checkpoint removed whatever was at FILE at the end, also
# a file that is not a checkpoint, through a link, or the surface read
# from standard input.  Refused before any work (exit 2), nothing lost; a
# run removes only the checkpoint it wrote.
surfgen -n 32 -o s32.surf
echo precious > precious.txt
check_status "--checkpoint on a file that is not a checkpoint: exit 2" 2 \
    gfmd-solve -q -p 0.05 --checkpoint precious.txt -o p.tsv s32.surf
check "  says so" grep -q 'precious.txt: the file exists and is not a gfmd-solve checkpoint' "$T_TMP/stderr"
check "  the file is kept" test "$(cat precious.txt)" = precious
check "  no rows written" test ! -e p.tsv
ln -s precious.txt plink.txt
check_status "--checkpoint through a link to such a file: exit 2" 2 \
    gfmd-solve -q -p 0.05 --checkpoint plink.txt -o p.tsv s32.surf
check "  the target is kept" test "$(cat precious.txt)" = precious
cp s32.surf keep.surf
cat keep.surf | gfmd-solve -q -p 0.05 --checkpoint keep.surf > p.tsv 2>/dev/null
check_rel "--checkpoint naming the surface read from standard input: exit 2" $? 2 0
check "  the surface is kept" cmp -s keep.surf s32.surf
gfmd-solve -q -p 0.05,0.1 --checkpoint new.surf -o p.tsv s32.surf
check_rel "--checkpoint on a new name: exit 0" $? 0 0
check "  its checkpoint removed at the end" test ! -e new.surf
# --- What decides the rows and the exit status survives a resume
# (version 6): --stall (a resumed run ran with the default 300, not the
# saved 0) and the finished rows that did not converge (a resumed run
# counted only its own).  Two pressures that cannot reach --tol 1e-15
# (residual ~2e-14 at 128^2) within --max-iter 12000, no stall: the
# first row is written unconverged, the signal lands in the second.
surfgen -q -n 128 --seed 3 -o s128.surf
# -o names a file that was there: the stopped run keeps it as it was
# (it was replaced by the one finished row), the row is in the checkpoint.
rm -f uc.surf
echo old > uc.tsv
gfmd-solve -j 1 -q --tol 1e-15 --stall 0 --max-iter 12000 -p 0.05,0.1 \
    --checkpoint uc.surf -o uc.tsv s128.surf 2>uc.err & pid=$!
i=0
while [ ! -f uc.surf ] && [ $i -lt 600 ] && kill -0 $pid 2>/dev/null; do sleep 0.05; i=$((i + 1)); done
kill -INT $pid 2>/dev/null; wait $pid
if [ -f uc.surf ] && head -c 4000 uc.surf | grep -aq '^meta.checkpoint.next = 1$'; then
	check "the checkpoint records --stall 0" grep -aq '^meta.checkpoint.stall = 0$' uc.surf
	check "  and one unconverged row" grep -aq '^meta.checkpoint.unconverged = 1$' uc.surf
	check "the -o file that was there is kept" test "$(cat uc.tsv)" = old
	check "  said so ($(head -c 300 uc.err))" grep -q 'uc.tsv was there before and is kept as it was; the rows of the 1 of 2 pressures done are in the checkpoint; state saved in uc.surf' uc.err
	gfmd-solve -q --stall 300 --resume uc.surf s128.surf > /dev/null 2>err
	check_rel "resume with another --stall: exit 1" $? 1 0
	check "  named ($(head -c 150 err))" grep -q 'checkpoint has --stall 0, this run 300' err
	gfmd-solve -j 1 -q --resume uc.surf -o uc2.tsv s128.surf 2>err; st=$?
	check_rel "resumed, both rows unconverged: exit 1" $st 1 0
	check "  both counted ($(tail -n 1 err | head -c 150))" grep -q '2 of 2 pressures did not converge' err
	check_rel "  the saved --stall 0 ran the second to --max-iter" "$(col uc2.tsv iterations 2)" 12000 0
else
	skip 9 "unconverged resume: the signal did not land in the second pressure"
fi
# --- The printed resume command leaves out --init however it was
# spelled (an abbreviation --ini printed it back, with --resume: refused).
gfmd-solve -j 1 -q -p 0.05 --displacement u128.surf -o /dev/null s128.surf
printed=0
for wait_s in 0.3 1 2 4; do
	rm -f ab.surf
	gfmd-solve -j 1 -q --tol 1e-15 --stall 0 --max-iter 1000000 -p 0.05 \
	    --ini u128.surf --checkpoint ab.surf -o ab.tsv s128.surf 2>ab.err & pid=$!
	sleep $wait_s
	kill -INT $pid 2>/dev/null; wait $pid
	grep -q 'resume with:' ab.err || continue
	printed=1
	cmd=$(sed -n 's/.*resume with: //p' ab.err)
	check "resume command without the abbreviated --init ($cmd)" \
	    test "$cmd" = "gfmd-solve -j 1 -q --tol 1e-15 --stall 0 --max-iter 1000000 -p 0.05 --checkpoint ab.surf -o ab.tsv s128.surf --resume ab.surf"
	break
done
[ $printed = 1 ] || skip 1 "resume command with --ini: no signal landed in the solve"
summary
