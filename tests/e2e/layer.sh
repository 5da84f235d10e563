#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# layer.sh - gfmd-solve --thickness end to end: a sine in full contact on
# a layer carries p + k_q A cos (lib/elastic/layer.h's k_q, computed here by awk
# from the closed form) with both methods, the approach adds p/k_0, a
# very thick layer is the half space, displacement control past full
# contact, the rows, the refusals, free boundaries (FIRE = CG, thick =
# the half space, adhesion), plasticity and Dugdale adhesion on a free
# layer, and contact-stats grouping by layer.
. "$RC_TOP/tests/e2e/lib.sh"
T=$T_TMP

# k_q A of a sine of wavelength 1 and amplitude A on a layer of
# thickness d, Poisson 0.3, E* = 1: phi from the closed form.
kqa() {
	awk -v d="$1" -v kind="$2" -v A="$3" 'function ch(x) { return (exp(x) + exp(-x)) / 2 }
		function sh(x) { return (exp(x) - exp(-x)) / 2 }
		BEGIN { q = 2 * 3.14159265358979324; t = q * d; nu = 0.3
		if (kind == "slip") phi = (2 * t + sh(2 * t)) / (ch(2 * t) - 1)
		else phi = ((3 - 4 * nu) * ch(2 * t) + 2 * t * t + 5 - 12 * nu + 8 * nu * nu) / ((3 - 4 * nu) * sh(2 * t) - 2 * t)
		printf "%.17g\n", q / 2 * phi * A }'
}

surfgen -q -n 64x4 --type sine --wavelength 1 --amplitude 0.01 -o "$T/sine.surf"
for m in fire cg; do
	for sub in bonded slip; do
		for th in 0.02 0.3; do
			gfmd-solve -q -j 1 --method $m --tol 1e-10 --pressure-abs 20 \
			    --thickness $th --substrate $sub --poisson 0.3 \
			    --pressure "$T/sig.surf" "$T/sine.surf" > "$T/s.tsv"
			check "$m $sub d=$th: converges" test $? -eq 0
			check_rel "$m $sub d=$th: full contact" "$(col "$T/s.tsv" a_r)" 1 0
			check_rel "$m $sub d=$th: sigma - p = k_q A cos" \
			    "$(amplitude "$T/sig.surf")" "$(kqa $th $sub 0.01)" 1e-8
			# k_0 = (1 - nu)^2 / ((1 - 2 nu) d) = 1.225 / d
			check_rel "$m $sub d=$th: approach = A + p/k_0" \
			    "$(col "$T/s.tsv" approach)" "$(awk -v d=$th 'BEGIN { printf "%.17g\n", 0.01 + 20 * d / 1.225 }')" 1e-10
			check "$m $sub d=$th: the layer in the row" test \
			    "$(col "$T/s.tsv" thickness) $(col "$T/s.tsv" substrate) $(col "$T/s.tsv" poisson)" = "$th $sub 0.3"
		done
	done
done

# --- A layer a hundred cells thick is the half space (phi = 1 to
# round-off): the same contact points and mean gap.
surfgen -q -n 64 --seed 3 -o "$T/r.surf"
gfmd-solve -q -j 1 -p 0.05 "$T/r.surf" > "$T/half.tsv"
gfmd-solve -q -j 1 -p 0.05 --thickness 100 --poisson 0.3 "$T/r.surf" > "$T/thick.tsv"
check_rel "thick layer: the half space's n_c" "$(col "$T/thick.tsv" n_c)" "$(col "$T/half.tsv" n_c)" 0
check_rel "thick layer: the half space's mean gap" "$(col "$T/thick.tsv" mean_gap)" "$(col "$T/half.tsv" mean_gap)" 1e-9
check "half space: thickness 0, substrate none" test "$(col "$T/half.tsv" thickness) $(col "$T/half.tsv" substrate)" = "0 none"

# --- Displacement control past full contact (a half space refuses it):
# the sine at approach A + 20 d / k_0 comes back at p = 20.
gfmd-solve -q -j 1 --tol 1e-10 --approach "$(awk 'BEGIN { printf "%.17g\n", 0.01 + 20 * 0.3 / 1.225 }')" \
    --thickness 0.3 --poisson 0.3 "$T/sine.surf" > "$T/ap.tsv"
check "approach past full contact on a layer: converges" test $? -eq 0
check_rel "approach past full contact: p = 20" "$(col "$T/ap.tsv" p)" 20 1e-8
check_status "approach past full contact on a half space: refused" 1 \
    gfmd-solve -q --approach 1 "$T/sine.surf"

# --- Refusals (exit 2, before any work).
check_status "--thickness without --poisson" 2 gfmd-solve --thickness 0.1 -p 0.1 "$T/r.surf"
check "--thickness without --poisson: says so" grep -q -- "--poisson" "$T/stderr"
check_status "--poisson without --thickness" 2 gfmd-solve --poisson 0.3 -p 0.1 "$T/r.surf"
check_status "--thickness 0" 2 gfmd-solve --thickness 0 --poisson 0.3 -p 0.1 "$T/r.surf"
check_status "--poisson 0.6" 2 gfmd-solve --thickness 0.1 --poisson 0.6 -p 0.1 "$T/r.surf"
check_status "--substrate glued" 2 gfmd-solve --thickness 0.1 --poisson 0.3 --substrate glued -p 0.1 "$T/r.surf"
check_status "--thickness with --checkpoint: accepted (recorded)" 0 gfmd-solve -q --thickness 0.1 --poisson 0.3 --checkpoint "$T/ck.surf" -p 0.1 "$T/r.surf"
check_status "--thickness --kernel pixel (periodic)" 2 gfmd-solve --thickness 0.1 --poisson 0.3 --kernel pixel -p 0.1 "$T/r.surf"
check_status "--thickness --kernel pixel --boundary periodic" 2 gfmd-solve --thickness 0.1 --poisson 0.3 --kernel pixel --boundary periodic -p 0.1 "$T/r.surf"
# free boundaries solve a layer with its pixel compliance: --kernel pixel
# names what they do anyway (the rows the same as without it)
gfmd-solve -q -j 1 --thickness 0.1 --poisson 0.3 --boundary free -p 0.1 "$T/r.surf" > "$T/kf0.tsv"
gfmd-solve -q -j 1 --thickness 0.1 --poisson 0.3 --boundary free --kernel pixel -p 0.1 "$T/r.surf" > "$T/kf1.tsv"
check "--thickness --kernel pixel --boundary free: accepted" test $? -eq 0
check "--kernel pixel on a free layer: the same rows" test "$(cut -f 1-20 "$T/kf0.tsv")" = "$(cut -f 1-20 "$T/kf1.tsv")"

# --- Free boundaries (the layer's pixel compliance,
# lib/elastic/elastic_layer_free.h).
# A non-periodic map is solved with free boundaries, a layer included;
# FIRE and CG agree on it; a layer 100 times thicker than the area is
# the free half space (its pressures to ~1e-7: the contact set, and the
# approach less by D(0) F = F(0) p L^2 / (pi d), F(0) = 1.37685 bonded
# nu 0.3, computed in test_layer.c).
surfgen -q -n 32 --seed 2 | surfwarp --detrend plane -o "$T/np.surf"
for m in fire cg; do
	gfmd-solve -q -j 1 --method $m --tol 1e-10 --pressure-abs 0.02 --thickness 0.05 \
	    --poisson 0.3 --substrate bonded "$T/np.surf" > "$T/f_$m.tsv"
	check "free layer, $m: converges" test $? -eq 0
	check "free layer, $m: free boundaries in the row" test "$(col "$T/f_$m.tsv" boundary)" = free
done
check_rel "free layer: FIRE's n_c = CG's" "$(col "$T/f_fire.tsv" n_c)" "$(col "$T/f_cg.tsv" n_c)" 0
check_rel "free layer: FIRE's approach = CG's" "$(col "$T/f_fire.tsv" approach)" "$(col "$T/f_cg.tsv" approach)" 1e-8
gfmd-solve -q -j 1 --method cg --tol 1e-10 --pressure-abs 0.02 "$T/np.surf" > "$T/f_half.tsv"
gfmd-solve -q -j 1 --method cg --tol 1e-10 --pressure-abs 0.02 --thickness 100 --poisson 0.3 "$T/np.surf" > "$T/f_thick.tsv"
check_rel "free thick layer: the half space's n_c" "$(col "$T/f_thick.tsv" n_c)" "$(col "$T/f_half.tsv" n_c)" 0
check_rel "free thick layer: approach less by D(0) F" \
    "$(awk -v a="$(col "$T/f_half.tsv" approach)" -v b="$(col "$T/f_thick.tsv" approach)" 'BEGIN { printf "%.17g\n", a - b }')" \
    "$(awk 'BEGIN { printf "%.17g\n", 1.37685 * 0.02 / (3.14159265358979 * 100) }')" 1e-4
check_status "free incompressible thin bonded layer: refused" 1 \
    gfmd-solve -q --thickness 1e-4 --poisson 0.5 --boundary free -p 0.1 "$T/r.surf"
check "refused: the message says why" grep -q "positive definite" "$T/stderr"
# adhesion through the same compliance, displacement control on free
# boundaries (the rigid level is the substrate's travel) and periodic
# ones (the substrate held, its spring k_0 on the mean mode)
gfmd-solve -q -j 1 --adhesion 1e-4 --range 0.01 --approach 0.002 --thickness 0.05 \
    --poisson 0.3 --boundary free "$T/np.surf" > "$T/f_adh.tsv"
check "free layer with adhesion under --approach: converges" test $? -eq 0
check_rel "free layer with adhesion: the approach held" "$(col "$T/f_adh.tsv" approach)" 0.002 1e-9
gfmd-solve -q -j 1 --adhesion 1e-4 --range 0.01 --approach 0.002 --thickness 0.05 \
    --poisson 0.3 --boundary periodic "$T/np.surf" > "$T/p_adh.tsv"
check "periodic layer with adhesion under --approach: converges" test $? -eq 0
check_rel "periodic layer with adhesion: the approach held" "$(col "$T/p_adh.tsv" approach)" 0.002 1e-9

# --- Plasticity on a layer: a cap that never binds (H = 4000 p) gives
# the elastic layer's contact; one that binds (H = 4 p) flattens points.
gfmd-solve -q -j 1 --method cg -p 0.05 --thickness 0.1 --poisson 0.3 "$T/r.surf" > "$T/le.tsv"
gfmd-solve -q -j 1 --method cg -p 0.05 --thickness 0.1 --poisson 0.3 --hardness 200 "$T/r.surf" > "$T/lh.tsv"
gfmd-solve -q -j 1 --method cg -p 0.05 --thickness 0.1 --poisson 0.3 --hardness 0.2 "$T/r.surf" > "$T/lp.tsv"
check_rel "layer, H = 4000 p: the elastic layer's n_c" "$(col "$T/lh.tsv" n_c)" "$(col "$T/le.tsv" n_c)" 0
check_rel "layer, H = 4000 p: the elastic layer's approach" "$(col "$T/lh.tsv" approach)" "$(col "$T/le.tsv" approach)" 1e-6
check_range "layer, H = 4 p: plastic points" "$(col "$T/lp.tsv" a_plastic)" 1e-9 1
# The effects combined on free boundaries: FIRE (on pressures) and the
# plastic CG solve one minimisation over the same box with the layer's
# pixel compliance, so their contact and plastic sets agree to the point
# and their approaches to the tolerance (tol 1e-9: 1e-7 relative).
for m in fire cg; do
	gfmd-solve -q -j 1 --method $m --tol 1e-9 --boundary free --pressure-abs 0.05 \
	    --thickness 0.1 --poisson 0.3 --hardness 0.2 "$T/r.surf" > "$T/fp_$m.tsv"
	check "free layer with a hardness, $m: converges" test $? -eq 0
done
check_rel "free plastic layer: FIRE's n_c = CG's" "$(col "$T/fp_fire.tsv" n_c)" "$(col "$T/fp_cg.tsv" n_c)" 0
check_rel "free plastic layer: FIRE's a_plastic = CG's" "$(col "$T/fp_fire.tsv" a_plastic)" "$(col "$T/fp_cg.tsv" a_plastic)" 0
check_range "free plastic layer: some points flow" "$(col "$T/fp_cg.tsv" a_plastic)" 1e-9 1
check_rel "free plastic layer: FIRE's approach = CG's" "$(col "$T/fp_fire.tsv" approach)" "$(col "$T/fp_cg.tsv" approach)" 1e-7
# Dugdale's law on a free layer: the load that an approach needed gives
# that approach back under load control (a stable state is the same
# equilibrium under either control; tol 1e-9).
gfmd-solve -q -j 1 --tol 1e-9 --adhesion 1e-4 --range 0.01 --law dugdale --approach 0.03 \
    --thickness 0.05 --poisson 0.3 --boundary free "$T/np.surf" > "$T/fd_a.tsv"
check "free layer, Dugdale, --approach: converges" test $? -eq 0
gfmd-solve -q -j 1 --tol 1e-9 --adhesion 1e-4 --range 0.01 --law dugdale \
    --pressure-abs "$(col "$T/fd_a.tsv" p)" --thickness 0.05 --poisson 0.3 \
    --boundary free "$T/np.surf" > "$T/fd_p.tsv"
check "free layer, Dugdale, the load: converges" test $? -eq 0
check_rel "free layer, Dugdale: the load gives the approach back" "$(col "$T/fd_p.tsv" approach)" 0.03 1e-6
check_rel "free layer, Dugdale: the same contact" "$(col "$T/fd_p.tsv" n_c)" "$(col "$T/fd_a.tsv" n_c)" 0

# --- contact-stats: the layer is a key (two thicknesses, two groups).
gfmd-solve -q -j 1 -p 0.05 --thickness 0.1 --poisson 0.3 "$T/r.surf" > "$T/l1.tsv"
gfmd-solve -q -j 1 -p 0.05 --thickness 0.2 --poisson 0.3 "$T/r.surf" > "$T/l2.tsv"
contact-stats -q --no-extrapolate -o "$T/cs.tsv" "$T/l1.tsv" "$T/l2.tsv" "$T/half.tsv"
check "contact-stats over layer rows" test $? -eq 0
check_rel "contact-stats: one group per layer and the half space" "$(awk 'END { print NR - 1 }' "$T/cs.tsv")" 3 0
summary
