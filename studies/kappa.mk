# SPDX-License-Identifier: GPL-3.0-or-later
# kappa.mk - kappa(p*) and kappa_c(p*) of self-affine surfaces, the
# machinery of Figures 4, 7 and 8 (included by kappa-pressure, anisotropy,
# warping after common.mk).  For every Hurst exponent in HS, schedule in
# SCHEDS, warp in WARPS and pressure in PRESSURES, SEEDS surfaces are solved
# at the discretisations EPS_C (eps_c = dx/lambda_s); contact-stats
# extrapolates eps_c -> 0 per seed (Richardson, linear) and averages over
# seeds.  The cell has L = 1, so lambda_r = eps_t and lambda_s = eps_f eps_t.
# Schedules (Eq. 27, eps = eps_ref (p/p_ref)^(1/4)):
#   const   eps_f = EF_REF, eps_t = ET_REF at every pressure
#   f       eps_f scaled, eps_t = ET_REF
#   ft      both scaled
# PK (Peklenik gamma, default 1): the grid is (n/PK) x (n PK) so that the
# shortest wavelength along each axis, gamma lambda_s along x and
# lambda_s/gamma along y, is sampled with the same eps_c.

HS        ?= 0.3 0.8
SCHEDS    ?= const ft
WARPS     ?= 0
PK        ?= 1
P_REF     ?= 0.2
EF_REF    ?= 0.03125
ET_REF    ?= 0.5
ifeq ($(FULL),1)
PRESSURES ?= 0.2 0.1 0.05 0.025 0.0125
SEEDS     ?= 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20
EPS_C     ?= 0.25 0.125 0.0625
else
PRESSURES ?= 0.2 0.1 0.05 0.025
SEEDS     ?= 1 2 3 4 5 6 7 8
EPS_C     ?= 0.25 0.125 0.0625
endif

k_ef = $(if $(filter f ft,$(1)),$(call schedule,$(EF_REF),$(P_REF),$(2)),$(EF_REF))
k_et = $(if $(filter ft,$(1)),$(call schedule,$(ET_REF),$(P_REF),$(2)),$(ET_REF))
k_ls = $(shell awk 'BEGIN { printf "%.6g", $(call k_ef,$(1),$(2)) * $(call k_et,$(1),$(2)) }')
k_n  = $(shell awk 'BEGIN { $(call evenup,1 / ($(3) * $(1) * $(2))); nx = n; \
	$(call evenup,$(2) / ($(3) * $(1))); print (nx == n ? n : nx "x" n) }')
# $(call k_surf,H,SCHED,P,EPS_C,SEED,W)
k_surf = n$(call k_n,$(call k_ls,$(2),$(3)),$(PK),$(4))_H$(1)_lr$(call k_et,$(2),$(3))_ls$(call k_ls,$(2),$(3))_seed$(5)$(if $(filter-out 1,$(PK)),_pk$(PK))$(if $(filter-out 0,$(6)),_w$(6))
k_sols = $(foreach p,$(PRESSURES),$(foreach s,$(SEEDS),$(foreach e,$(EPS_C), \
	$(OUT)/sol/$(call k_surf,$(1),$(2),$(p),$(e),$(s),$(3))__p$(p).tsv)))

# one contact-stats run per curve H+schedule+w (warps may be negative).
# No pipes from a tool: sh has no pipefail, and a failure must stop make.
KCURVES = $(foreach h,$(HS),$(foreach c,$(SCHEDS),$(foreach w,$(WARPS),H$(h)+$(c)+w$(w))))
$(OUT)/kappa/%.tsv: $$(call k_sols,$$(subst H,,$$(word 1,$$(subst +, ,$$*))),$$(word 2,$$(subst +, ,$$*)),$$(subst w,,$$(word 3,$$(subst +, ,$$*))))
	@mkdir -p $(@D)
	$(CSTATS) $^ -o $@.cs
	awk -F'\t' -v curve=$* 'NR == 1 { print "curve\t" $$0; next } { print curve "\t" $$0 }' $@.cs > $@
	rm -f $@.cs

$(OUT)/kappa.tsv: $(foreach k,$(KCURVES),$(OUT)/kappa/$(k).tsv)
	awk -F'\t' 'FNR == 1 { delete c; for (i = 1; i <= NF; i++) c[$$i] = i; if (NR > 1) next; \
	    print "curve\tp_star\tkappa\tkappa_err\tkappa_c\tkappa_c_err\ta_r\ta_r_err\tn_seeds\tlambda_r\tlambda_s"; next } \
	    { print $$c["curve"] "\t" $$c["p_star"] "\t" $$c["kappa"] "\t" $$c["kappa_err"] "\t" $$c["kappa_c"] "\t" \
	      $$c["kappa_c_err"] "\t" $$c["a_r"] "\t" $$c["a_r_err"] "\t" $$c["n_seeds"] "\t" $$c["lambda_r"] "\t" $$c["lambda_s"] }' $^ > $@

$(OUT)/kappa.png: $(OUT)/kappa.tsv $(COMMON_DIR)kappa.gp
	$(GNUPLOT) -e "data='$<'; out='$@'; curves='$(KCURVES)'; title='$(KTITLE)'" $(COMMON_DIR)kappa.gp

# Name every solution in an explicit rule: files that only pattern rules
# mention are intermediate, and make would not notice a missing one (a new
# pressure or seed) while the curve's table exists.
K_ALLSOLS = $(foreach h,$(HS),$(foreach c,$(SCHEDS),$(foreach w,$(WARPS),$(call k_sols,$(h),$(c),$(w)))))
$(OUT)/kappa.tsv: | $(K_ALLSOLS)
