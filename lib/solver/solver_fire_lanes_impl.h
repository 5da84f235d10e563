/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_fire_lanes_impl.h - the template of solver_fire_wide.c's loops on
 * vectors of LANES doubles, included there once per instruction set with
 * LANES and LANES_NAME(x) defined and the target set by `#pragma GCC
 * target'.  No include guard: that is its use.  The loop does the whole
 * vectors of [k0, k1); its caller's loop does the rest.  The vectors are
 * loaded and stored with memcpy (no alignment assumed) and never cross a
 * function boundary (no ABI question). */
typedef double LANES_NAME(vd) __attribute__((vector_size(8 * LANES)));
typedef long long LANES_NAME(vl) __attribute__((vector_size(8 * LANES)));
typedef unsigned char LANES_NAME(vb) __attribute__((vector_size(LANES)));

/* update_range's loop (solver_fire.c) on vectors: the same operations
 * as its two-lane loop, lane for lane; returns the first point left. */
static size_t
LANES_NAME(update)(unsigned char *contact, const double *h, double *u,
    double *v, const double *a, const rc__fire_step *st, size_t k0,
    size_t k1)
{
	double dt = st->dt, mix_v = st->mix_v, mix_a = st->mix_a;
	int restart = st->restart;
	size_t k;

	for (k = k0; k + LANES <= k1; k += LANES) {
		LANES_NAME(vd) ak, vk, uk, hk;
		LANES_NAME(vl) held, clamp;
		LANES_NAME(vb) c;

		memcpy(&c, contact + k, sizeof(c));
		memcpy(&ak, a + k, sizeof(ak));
		memcpy(&vk, v + k, sizeof(vk));
		memcpy(&uk, u + k, sizeof(uk));
		memcpy(&hk, h + k, sizeof(hk));
		held = __builtin_convertvector(c, LANES_NAME(vl)) != 0;
		ak = (LANES_NAME(vd))((LANES_NAME(vl))ak & ~held);
		if (restart)
			vk = (LANES_NAME(vd)){ 0 };
		vk = mix_v * (vk + dt * ak) + mix_a * ak;
		uk = uk + dt * vk;
		clamp = uk <= hk;
		uk = (LANES_NAME(vd))(((LANES_NAME(vl))hk & clamp) |
		    ((LANES_NAME(vl))uk & ~clamp));
		vk = (LANES_NAME(vd))((LANES_NAME(vl))vk & ~clamp);
		c = __builtin_convertvector(clamp & RC__ON_WALL, LANES_NAME(vb));
		memcpy(u + k, &uk, sizeof(uk));
		memcpy(v + k, &vk, sizeof(vk));
		memcpy(contact + k, &c, sizeof(c));
	}
	return k;
}
