# SPDX-License-Identifier: GPL-3.0-or-later
# outputs.sh - at most one output goes to standard output, binary never to
# a terminal; the refusal is a usage error (exit 2) that writes nothing.
# An output may be its input where it is the same kind of thing (surfwarp
# -o in.surf in.surf); an output of another kind that names an input (a
# table over the surface, a PNG over rows) is refused, also through another
# path to the same file, and the input is left as it was.
# Targets that are not regular files are written, never replaced: a device
# stays a device, a FIFO gets the data, a symbolic link stays a link to the
# updated file, /dev/stdout keeps a shell's >>.  Two outputs of a run never
# name the same file, and an output never names the file on standard input.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
surfgen -n 16 -o s.surf
check_status "surfgen --png - with the grid on stdout" 2 surfgen -n 16 --png -
check_status "surfwarp --png - with the grid on stdout" 2 surfwarp --png - s.surf
check_status "surfstat --psd2d - with the table on stdout" 2 surfstat --psd2d - s.surf
check_status "surfstat --gnuplot - with the table on stdout" 2 surfstat --psd --gnuplot - s.surf
check_status "contact-stats --gnuplot - with the table on stdout" 2 contact-stats --gnuplot - /dev/null
# One of them on stdout is fine: a real PNG comes out.
surfgen -n 16 --png - -o t.surf > p.png
check "surfgen --png - alone writes a PNG" [ "$(head -c 4 p.png | od -An -c | tr -d ' ')" = "211PNG" ]
# Binary to a terminal is refused (script(1) gives the tool a terminal).
if have_pty; then
	script -qec "surfgen -n 8 --png - -o u.surf" /dev/null > tty.out 2>&1
	check "surfgen --png - to a terminal is refused" grep -q "terminal; refusing" tty.out
	check "nothing written when refused" [ ! -e u.surf ]
else
	skip 2 "script(1) not installed or no pseudo-terminal here (/dev/pts): binary output to a terminal not tested (apt-get install bsdutils)"
fi

# --- outputs against inputs ------------------------------------------------
surfgen -n 32 --seed 4 -o h.surf
cp h.surf keep.surf
surfwarp -w 2 -o w.surf h.surf
cp h.surf inplace.surf
surfwarp -w 2 -o inplace.surf inplace.surf
# the 32 x 32 float64 values (the headers differ in their history lines)
tail -c 8192 w.surf > fresh.bin
tail -c 8192 inplace.surf > inplace.bin
check "surfwarp -o equal to its input: the same heights as a fresh output" \
    cmp -s fresh.bin inplace.bin
check_status "surfstat -o the input" 2 surfstat -o h.surf h.surf
check_status "surfstat --psd2d the input, through ./" 2 surfstat --psd2d ./h.surf h.surf
check_status "surfstat -o the mask" 2 surfstat -o keep.surf --mask keep.surf h.surf
check_status "gfmd-solve -o the indenter" 2 gfmd-solve -p 0.1 -o h.surf h.surf
check_status "gfmd-solve --gap the indenter" 2 gfmd-solve -p 0.1 --gap h.surf h.surf
check_status "gfmd-solve --checkpoint the indenter" 2 gfmd-solve -p 0.1 --checkpoint h.surf h.surf
check_status "surfwarp --png the input" 2 surfwarp -w 1 --png h.surf h.surf
check "every refusal left the input as it was" cmp -s h.surf keep.surf
gfmd-solve -q -p 0.1 -o rows.tsv h.surf
cp rows.tsv rows.keep
check_status "contact-stats -o an input" 2 contact-stats --no-extrapolate -o rows.tsv rows.tsv
check "contact-stats left its input as it was" cmp -s rows.tsv rows.keep

# --- targets that are not regular files -----------------------------------
# As root the devices are private nodes made here (c 1 3 is null, c 1 7 is
# full), so that a regression cannot replace the machine's /dev/null;
# otherwise the real ones, which a normal user cannot replace anyway.
if mknod null c 1 3 2>/dev/null && mknod full c 1 7 2>/dev/null; then
	NULLDEV=$PWD/null FULLDEV=$PWD/full
else
	NULLDEV=/dev/null FULLDEV=/dev/full
fi
isdev() { [ "$(stat -c %F "$1")" = "character special file" ]; }
check_status "surfgen -o NULL" 0 surfgen -n 8 -o "$NULLDEV"
check "surfgen -o NULL: still a character device" isdev "$NULLDEV"
check_status "surfgen --png NULL" 0 surfgen -n 8 --png "$NULLDEV" -o "$NULLDEV"
check "surfgen --png NULL: still a character device" isdev "$NULLDEV"
check_status "gfmd-solve, every field, -o and --png NULL" 0 gfmd-solve -q -p 0.1 \
    --gap "$NULLDEV" --pressure "$NULLDEV" --contact "$NULLDEV" \
    --displacement "$NULLDEV" --png "$NULLDEV" -o "$NULLDEV" h.surf
check "gfmd-solve fields to NULL: still a character device" isdev "$NULLDEV"
check_status "gfmd-solve --checkpoint NULL over two pressures" 0 gfmd-solve -q \
    -p 0.1,0.2 --checkpoint "$NULLDEV" -o "$NULLDEV" h.surf
check "a finished run does not remove a device checkpoint" isdev "$NULLDEV"
check_status "surfstat --psd2d, --gnuplot NULL" 0 surfstat --psd --psd2d "$NULLDEV" \
    --gnuplot "$NULLDEV" -o "$NULLDEV" h.surf
check "surfstat outputs to NULL: still a character device" isdev "$NULLDEV"
check_status "contact-stats --gnuplot NULL" 0 contact-stats --no-extrapolate \
    --gnuplot "$NULLDEV" -o "$NULLDEV" rows.tsv
check "contact-stats outputs to NULL: still a character device" isdev "$NULLDEV"
check_status "surfgen --wisdom NULL" 0 surfgen -n 8 --fft-effort measure \
    --wisdom "$NULLDEV" -o "$NULLDEV"
check "wisdom to NULL: still a character device" isdev "$NULLDEV"
# A full disk is an error, exit 1, with the reason.
full_fails() {	# full_fails DESC CMD...: exit 1 and "No space left"
	d=$1; shift
	"$@" >/dev/null 2>full.err; st=$?
	if [ "$st" = 1 ] && grep -q "No space left" full.err; then pass "$d"
	else fail "$d: exit $st, expected 1 and 'No space left' ($(head -c 200 full.err))"; fi
}
full_fails "surfgen -o FULL" surfgen -n 8 -o "$FULLDEV"
full_fails "surfgen --png FULL" surfgen -n 8 --png "$FULLDEV" -o "$NULLDEV"
full_fails "surfwarp -o FULL" surfwarp -w 1 -o "$FULLDEV" h.surf
full_fails "surfstat -o FULL" surfstat -o "$FULLDEV" h.surf
full_fails "surfstat --psd2d FULL" surfstat --psd2d "$FULLDEV" -o "$NULLDEV" h.surf
full_fails "surfstat --gnuplot FULL (it crashed)" surfstat --gnuplot "$FULLDEV" -o "$NULLDEV" h.surf
full_fails "gfmd-solve -o FULL" gfmd-solve -q -p 0.1 -o "$FULLDEV" h.surf
full_fails "gfmd-solve --gap FULL" gfmd-solve -q -p 0.1 --gap "$FULLDEV" -o "$NULLDEV" h.surf
full_fails "gfmd-solve --png FULL" gfmd-solve -q -p 0.1 --png "$FULLDEV" -o "$NULLDEV" h.surf
full_fails "contact-stats -o FULL" contact-stats --no-extrapolate -o "$FULLDEV" rows.tsv
full_fails "contact-stats --gnuplot FULL" contact-stats --no-extrapolate \
    --gnuplot "$FULLDEV" -o "$NULLDEV" rows.tsv
check "FULL is still a character device" isdev "$FULLDEV"
# A FIFO gets the data (a reader with a time limit: a tool that replaced
# the FIFO would leave it waiting).  8 x 8 float64 = the last 512 bytes.
surfgen -n 8 -o ref.surf
mkfifo fifo
timeout 20 cat fifo > fifo.out & reader=$!
timeout 20 surfgen -n 8 -o fifo; st=$?
wait $reader
check "surfgen -o FIFO: exit 0" [ "$st" = 0 ]
check "surfgen -o FIFO: the reader got the grid" \
    [ "$(tail -c 512 fifo.out | od -An -tx1)" = "$(tail -c 512 ref.surf | od -An -tx1)" ]
check "surfgen -o FIFO: still a FIFO" [ "$(stat -c %F fifo)" = fifo ]
timeout 20 cat fifo > fifo.tsv & reader=$!
timeout 20 gfmd-solve -q -p 0.1 -o fifo h.surf; st=$?
wait $reader
check "gfmd-solve -o FIFO: the reader got the table" \
    [ "$st/$(col fifo.tsv a_r)" = "0/$(col rows.tsv a_r)" ]
# A symbolic link stays a link; the file it names is updated (also when
# the link dangles: the file is created where it points).
surfgen -n 8 --seed 1 -o target.surf
ln -s target.surf link.surf
surfgen -n 8 --seed 2 -o seed2.surf
surfgen -n 8 --seed 2 -o link.surf
check "-o LINK: still a link" [ -L link.surf ]
check "-o LINK: the target has the new heights" \
    [ "$(tail -c 512 target.surf | od -An -tx1)" = "$(tail -c 512 seed2.surf | od -An -tx1)" ]
ln -s sub/made.surf dangling.surf
mkdir sub
surfgen -n 8 -o dangling.surf
check "-o DANGLING LINK: the file is made where it points" [ -L dangling.surf ] && [ -f sub/made.surf ]
gfmd-solve -q -p 0.1 --gap gapt.surf h.surf > /dev/null
ln -s gapt.surf gapl.surf
check_status "gfmd-solve --gap LINK" 0 gfmd-solve -q -p 0.2 --gap gapl.surf -o "$NULLDEV" h.surf
check "--gap LINK: still a link to an updated field" [ -L gapl.surf ] && grep -aq "p_star = 0.2" gapt.surf
# /dev/stdout is standard output itself: a shell's >> appends.
echo "kept line" > app.out
surfgen -n 4 -o /dev/stdout >> app.out
check "-o /dev/stdout after >>: the earlier content is kept" [ "$(head -n 1 app.out)" = "kept line" ]
check "-o /dev/stdout after >>: the grid follows" [ "$(sed -n 2p app.out | cut -c1-5)" = "#surf" ]
# No temporary file was left anywhere above.
check "no temporary file left" [ -z "$(ls -A | grep '^\.')" ]

# --- two files of one run that are the same file ----------------------------
check_status "surfgen -o and --png the same new file" 2 surfgen -n 8 -o same.x --png ./same.x
check "  nothing written" [ ! -e same.x ]
check_status "gfmd-solve --checkpoint = -o" 2 gfmd-solve -q -p 0.1 --checkpoint r2.tsv -o r2.tsv h.surf
check_status "gfmd-solve --checkpoint = --gap" 2 gfmd-solve -q -p 0.1 --checkpoint g.surf --gap g.surf -o r3.tsv h.surf
check_status "gfmd-solve --gap = --pressure" 2 gfmd-solve -q -p 0.1 --gap f.surf --pressure ./f.surf h.surf
check_status "gfmd-solve --png = -o (existing, through a link)" 2 gfmd-solve -q -p 0.1 --png link.surf -o target.surf h.surf
check_status "surfstat --psd2d = --gnuplot" 2 surfstat --psd --psd2d p.surf --gnuplot p.surf h.surf
check_status "surfgen --wisdom = -o" 2 surfgen -n 8 --wisdom w.surf -o w.surf
check_status "contact-stats --gnuplot = -o" 2 contact-stats --no-extrapolate --gnuplot k.gp -o k.gp rows.tsv
gfmd-solve -q -p 0.1,0.2 --max-iter 2 --checkpoint ck.surf -o "$NULLDEV" h.surf 2>/dev/null
cp h.surf ck.surf
check_status "gfmd-solve --resume ck -o ck" 2 gfmd-solve -q --resume ck.surf -o ck.surf h.surf
check "  the checkpoint is left as it was" cmp -s ck.surf h.surf
check "  no row file was made" [ ! -e r2.tsv ] && [ ! -e r3.tsv ] && [ ! -e g.surf ] && [ ! -e f.surf ]
# Standard input redirected from a file that is also an output.
check_status "gfmd-solve -o FILE < FILE" 2 gfmd-solve -q -p 0.1 -o h.surf < h.surf
check_status "gfmd-solve --gap FILE < FILE" 2 gfmd-solve -q -p 0.1 --gap h.surf < h.surf
check_status "surfstat -o FILE < FILE" 2 surfstat -o h.surf < h.surf
check_status "surfwarp --png FILE < FILE" 2 surfwarp -w 1 --png h.surf < h.surf
check_status "contact-stats -o FILE < FILE" 2 contact-stats --no-extrapolate -o rows.tsv < rows.tsv
check "every refusal left the inputs as they were" cmp -s h.surf keep.surf && cmp -s rows.tsv rows.keep
grep -q "the same file as standard input" "$T_TMP/stderr"
check "the refusal names standard input" [ $? = 0 ]
# surfwarp may replace its input (the same kind, read in full first),
# named or on standard input: the heights equal a fresh output's.
cp h.surf inplace2.surf
check_status "surfwarp -o FILE < FILE (in place)" 0 surfwarp -w 2 -o inplace2.surf < inplace2.surf
tail -c 8192 inplace2.surf > inplace2.bin
check "  the same heights as a fresh output" cmp -s fresh.bin inplace2.bin

# --- a signal while an output is written ----------------------------------
# SIGTERM while a big output is being written (about 1 s for a 1024^2
# text grid): the tool dies of the signal, says so, and leaves no
# .NAME.XXXXXX temporary, and what it leaves is complete (outputs finished
# before it are kept).  The tool is stopped (SIGSTOP) as soon as its
# temporary file is seen, and the file looked for again while it cannot
# move: the signal, sent then and delivered on SIGCONT, finds that file
# however loaded the machine is.  A tool that ended, or finished the file,
# before it was stopped is said so and skipped, never counted as a pass
# or a failure.
killed_while_writing() {	# DESC RE CMD...: run in sig/, killed while a temporary .RE.* exists
	what=$1 name=$2; shift 2
	rm -rf sig; mkdir sig
	(cd sig && exec "$@") 2>sig.err >/dev/null & pid=$!
	n=0
	while [ $n -lt 600 ] && ! ls -A sig | grep -Eq "^\.($name)\." && kill -0 $pid 2>/dev/null; do
		sleep 0.05; n=$((n + 1))
	done
	kill -STOP $pid 2>/dev/null; stopped=$?
	seen=$(ls -A sig | tr '\n' ' ')
	kill -TERM $pid 2>/dev/null
	kill -CONT $pid 2>/dev/null
	wait $pid; st=$?
	[ $stopped = 0 ] || { skip 4 "$what: the tool ended before the signal (exit $st)"; return; }
	if ! echo "$seen" | tr ' ' '\n' | grep -Eq "^\.($name)\."; then
		skip 4 "$what: no temporary file when the signal came ($seen; exit $st)"; return
	fi
	check "$what: dies of SIGTERM (exit $st, want 143)" [ "$st" = 143 ]
	check "$what: no temporary file left ($(ls -A sig | tr '\n' ' '))" \
	    [ -z "$(ls -A sig | grep '^\.')" ]
	# what is there was finished before the signal: complete, readable
	ok=1
	for f in sig/*.txt; do
		[ -e "$f" ] || continue
		surfstat -q -L 1 -o /dev/null "$f" 2>/dev/null || ok=0
	done
	check "$what: every output left is complete" [ $ok = 1 ]
	check "$what: says so ($(head -c 200 sig.err))" grep -q "terminated (SIGTERM); unfinished output files removed" sig.err
}
killed_while_writing "surfgen -o big.txt" 'big\.txt' surfgen -n 1024 -o big.txt
surfgen -n 512 -o big.surf
killed_while_writing "gfmd-solve, fields" '(gap|p|u)\.txt' gfmd-solve -q --max-iter 1 -p 0.1 \
    --gap gap.txt --pressure p.txt --displacement u.txt -o rows.tsv ../big.surf
surfgen -n 1024 -o big1024.surf
killed_while_writing "surfwarp -o w.txt" 'w\.txt' surfwarp -w 2 -o w.txt ../big1024.surf
killed_while_writing "surfstat --psd2d" 'psd\.txt' surfstat -q --psd2d psd.txt -o row.tsv ../big1024.surf
# contact-stats writes little itself; its longest output is --png, made by
# gnuplot into the temporary file beside the target.  A stand-in gnuplot
# that waits on a FIFO holds it there for as long as the check needs; the
# temporary gnuplot script (in TMPDIR) must go too.
mkdir -p gpbin gptmp
mkfifo gpgate
printf '#!/bin/sh\n: > "%s"\nread x < "%s"\nexit 1\n' "$PWD/gpstarted" "$PWD/gpgate" > gpbin/gnuplot
chmod +x gpbin/gnuplot
gfmd-solve -q -p 0.05,0.1 -o cs-rows.tsv s.surf
killed_while_writing "contact-stats --png" 'k\.png' env TMPDIR="$PWD/gptmp" \
    PATH="$PWD/gpbin:$PATH" contact-stats -q --no-extrapolate --png k.png -o t.tsv ../cs-rows.tsv
check "contact-stats --png: its gnuplot script is removed too ($(ls -A gptmp | tr '\n' ' '))" \
    [ -z "$(ls -A gptmp)" ]
# release the stand-in (if it never started, nobody reads: time out)
[ -e gpstarted ] && timeout 10 sh -c 'echo > "$1"' sh gpgate

# --- any command line makes a file the toolkit reads back ------------------
# A control character or a byte that is not UTF-8 in an argument (here a
# file name) is recorded in the history as \xNN or as it is; the result
# is read by every reader, and a checkpoint of it resumes.
ctl=$(printf 'a\001b\033c\351.surf')
check_status "surfgen -o NAME-WITH-CONTROLS" 0 surfgen -n 8 -o "$ctl"
check_status "  surfstat reads it back" 0 surfstat -o /dev/null "$ctl"
check "  the history holds \\x01 and \\x1b" grep -aq 'a\\x01b\\x1bc' "$ctl"
check_status "  surfwarp, through its own history, and back" 0 sh -c 'surfwarp -w 1 -o "$1" "$1" && surfstat -o /dev/null "$1"' sh "$ctl"
ckc=$(printf 'ck\002.surf')
gfmd-solve -q -p 0.1,0.2 --max-iter 2 --checkpoint "$ckc" -o /dev/null "$ctl" 2>/dev/null
check "  gfmd-solve on it leaves no checkpoint at the end" [ ! -e "$ckc" ]

# --- closed standard descriptors ------------------------------------------
# With stderr closed the warning (not converged) must not land in the
# table that took its descriptor; with stdout closed a table fails.
gfmd-solve -q -p 0.1 --max-iter 3 -o closed.tsv h.surf 2>&-
check "stderr closed: the table has no warning in it" [ "$(grep -c 'converged' closed.tsv)" = 0 ]
check "stderr closed: the table is whole (header and one row)" [ "$(awk 'END { print NR }' closed.tsv)" = 2 ]
check_status "stdout closed: a table to stdout fails" 1 sh -c 'surfstat h.surf >&-'

# --- outputs that could not be written are refused before any work --------
check_status "gfmd-solve --gap in a missing directory" 2 gfmd-solve -q -p 0.1 --gap nodir/g.surf h.surf
check_status "gfmd-solve -o ''" 2 gfmd-solve -q -p 0.1 -o '' h.surf
check_status "gfmd-solve --checkpoint a directory" 2 gfmd-solve -q -p 0.1 --checkpoint sub h.surf
check_status "surfgen -o in a missing directory" 2 surfgen -n 8 -o nodir/x.surf
check_status "surfstat --gnuplot in a missing directory" 2 surfstat --psd --gnuplot nodir/x.gp h.surf
summary
