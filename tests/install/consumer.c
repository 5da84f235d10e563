/* SPDX-License-Identifier: GPL-3.0-or-later */
/* consumer.c - a program outside the project, built against the installed
 * library through pkg-config (tests/e2e/install.sh): it generates a
 * surface, checks its rms height against an identity computed here, writes
 * it, reads it back and compares every value. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <roughcontact/roughcontact.h>

int
main(int argc, char **argv)
{
	rc_synth_params p;
	rc_err err;
	rc_grid *g, *back;
	double sum = 0, sum2 = 0, rms;
	size_t n;

	if (argc != 2) {
		fprintf(stderr, "usage: consumer FILE.surf\n");
		return 2;
	}
	rc_synth_defaults(&p);
	p.nx = p.ny = 64;
	p.rms_height = 0.5;
	if ((g = rc_synth(&p, &err)) == NULL) {
		fprintf(stderr, "consumer: %s\n", err.msg);
		return 1;
	}
	n = rc_grid_size(g);
	for (size_t i = 0; i < n; i++) {
		sum += g->z[i];
		sum2 += g->z[i] * g->z[i];
	}
	rms = sqrt(sum2 / (double)n - (sum / (double)n) * (sum / (double)n));
	if (rc_grid_write(g, argv[1], RC_FMT_SURF, &err) != 0 ||
	    (back = rc_grid_read(argv[1], NULL, &err)) == NULL) {
		fprintf(stderr, "consumer: %s\n", err.msg);
		return 1;
	}
	printf("rms_height\t%.17g\n", rms);
	printf("same_values\t%d\n", back->nx == g->nx && back->ny == g->ny &&
	    memcmp(back->z, g->z, n * sizeof(double)) == 0);
	rc_grid_free(back);
	rc_grid_free(g);
	return 0;
}
