# SPDX-License-Identifier: GPL-3.0-or-later
# common.mk - rules shared by the studies (and bench/accuracy).
#
# Every intermediate is a file whose name says how it was made, so make
# recomputes exactly what a changed parameter touches and a second make does
# nothing:
#   $(OUT)/surf/NAME.surf          a surface; NAME is words joined by "_":
#       n256 | n256x1024   grid points          H0.8     Hurst exponent
#       lr0.5  ls0.03125   lambda_r, lambda_s   rolloff  flat C(q) below q_r
#       pk4    Peklenik    seed3  random seed   hx2      harmonic exponent
#       w2     warp (Eq. 4), rescaled to rms gradient 1  flip  h -> -h
#   $(OUT)/sol/NAME__p0.05.tsv     gfmd-solve row of surface NAME at p* 0.05;
#       further "__" words: mfire|mcg (method), tol1e-6 (tolerance),
#       hard0.5 (--hardness, implies mcg), th0.125 (an elastic layer of
#       that --thickness), nu0.3 (its --poisson), slip (its --substrate),
#       kpixel (gfmd-solve --kernel pixel), adh0.001 rho0.002 (--adhesion
#       and its --range), fd (--fd: gbar and gbar_c by finite differences)
#   $(OUT)/stat/NAME.tsv           surfstat scalars of surface NAME
# A study lists the files its figure needs and reduces them with
# contact-stats, awk and gnuplot.  Tools are not prerequisites (other
# people rebuild them while studies run); after changing a tool run
# `make clean`.
#
# Variables a user may set: BIN (the tools), OUT (where files go),
# FULL=1 (paper-size parameters), SOLVE_J (threads per solve; default the
# tools' own: one thread under make -j N, all cores under a serial make).

COMMON_DIR := $(dir $(lastword $(MAKEFILE_LIST)))
TOP   ?= $(abspath $(COMMON_DIR)..)
BIN   ?= $(TOP)/bin
OUT   ?= out
FULL  ?= 0
SOLVE_J ?=
GNUPLOT ?= gnuplot

SURFGEN  = $(BIN)/surfgen -q
SURFWARP = $(BIN)/surfwarp -q
SURFSTAT = $(BIN)/surfstat -q
SOLVE    = $(BIN)/gfmd-solve -q $(if $(SOLVE_J),-j $(SOLVE_J))
CSTATS   = $(BIN)/contact-stats -q

.DEFAULT_GOAL := all

# No implicit rules; intermediates the next run reuses are kept (not
# .SECONDARY: without prerequisites it would let make skip missing files).
.SUFFIXES:
.PRECIOUS: $(OUT)/surf/%.surf $(OUT)/sol/%.tsv $(OUT)/stat/%.tsv
.DELETE_ON_ERROR:
.SECONDEXPANSION:

# words of a NAME, and the value of the word that starts with a key
words_of = $(subst _, ,$(1))
val = $(patsubst $(1)%,%,$(filter $(1)%,$(call words_of,$(2))))
has = $(filter $(1),$(call words_of,$(2)))

# surfgen options of a surface NAME
genopts = -n $(call val,n,$(1)) \
	$(if $(call val,hx,$(1)),--type harmonic --exponent $(call val,hx,$(1)), \
	-H $(call val,H,$(1)) --lambda-r $(call val,lr,$(1)) \
	--lambda-s $(call val,ls,$(1)) --seed $(call val,seed,$(1)) \
	$(if $(call has,rolloff,$(1)),--rolloff) \
	$(if $(call val,pk,$(1)),--peklenik $(call val,pk,$(1))))
warpopts = $(if $(call val,w,$(1)),-w $(call val,w,$(1)) --rms-gradient 1) \
	$(if $(call has,flip,$(1)),--flip)

$(OUT)/surf/%.surf:
	@mkdir -p $(@D)
	$(SURFGEN) $(call genopts,$*) -o $(if $(strip $(call warpopts,$*)),$@.raw.surf,$@)
	$(if $(strip $(call warpopts,$*)),$(SURFWARP) $(call warpopts,$*) -o $@ $@.raw.surf && rm -f $@.raw.surf)

# A solution: the surface is everything before the first "__".
surf_of = $(firstword $(subst __, ,$(1)))
solve_words = $(wordlist 2,99,$(subst __, ,$(1)))
solveopts = -p $(patsubst p%,%,$(filter p%,$(call solve_words,$(1)))) \
	$(patsubst m%,--method %,$(filter m%,$(call solve_words,$(1)))) \
	$(patsubst tol%,--tol %,$(filter tol%,$(call solve_words,$(1)))) \
	$(patsubst hard%,--method cg --hardness %,$(filter hard%,$(call solve_words,$(1)))) \
	$(patsubst th%,--thickness %,$(filter th%,$(call solve_words,$(1)))) \
	$(patsubst nu%,--poisson %,$(filter nu%,$(call solve_words,$(1)))) \
	$(if $(filter slip,$(call solve_words,$(1))),--substrate slip) \
	$(if $(filter fd,$(call solve_words,$(1))),--fd) \
	$(patsubst k%,--kernel %,$(filter k%,$(call solve_words,$(1)))) \
	$(patsubst adh%,--adhesion %,$(filter adh%,$(call solve_words,$(1)))) \
	$(patsubst rho%,--range %,$(filter rho%,$(call solve_words,$(1))))

$(OUT)/sol/%.tsv: $(OUT)/surf/$$(call surf_of,$$*).surf
	@mkdir -p $(@D)
	$(SOLVE) $(call solveopts,$*) -o $@ $<

$(OUT)/stat/%.tsv: $(OUT)/surf/%.surf
	@mkdir -p $(@D)
	$(SURFSTAT) -o $@ $<

# grid points per side for a cell of length 1, cutoff LS and eps_c = dx/LS,
# rounded up to an even number (dx never exceeds eps_c LS, so surfgen's
# lambda_s >= 2 dx holds for eps_c <= 1/2): $(call grid,LS,EPS_C)
evenup = x = $(1); n = 2 * int(x / 2); if (n < x - 1e-9) n += 2; if (n < 4) n = 4
grid = $(shell awk 'BEGIN { $(call evenup,1 / ($(2) * $(1))); print n }')
# $(call schedule,EPS_REF,P_REF,P): Eq. 27, eps = eps_ref (p/p_ref)^(1/4)
schedule = $(shell awk 'BEGIN { printf "%.6g", $(1) * ($(3) / $(2)) ^ 0.25 }')

# $(call tsvcat,FILES): rows of many one-header TSVs under one header; files
# whose headers differ (made by different versions of a tool) are an error,
# not a silent shift of columns: make clean and run again.
tsvcat = awk 'FNR == 1 { if (NR == 1) h = $$0; else if ($$0 != h) { \
	print FILENAME ": header differs from the first file'"'"'s; make clean" > "/dev/stderr"; exit 1 } \
	else next } { print }' $(1)

.PHONY: clean
clean:
	rm -rf $(OUT)
