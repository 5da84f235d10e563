/* spectral.c - spectral gradient, Laplacian, rms gradient. */
#include "spectral.h"

#include <math.h>
#include <string.h>

/* Load the grid into fft->real and transform; makes a plan if needed. */
static int
transform(const rc_grid *g, rc_fft *fft, rc_fft *own, rc_fft **use, rc_err *err)
{
	if (fft == NULL) {
		if (rc_fft_init(own, g->nx, g->ny, RC_FFT_ESTIMATE, err) != 0)
			return -1;
		fft = own;
	} else if (fft->nx != g->nx || fft->ny != g->ny)
		return rc_seterr(err, "internal: FFT plan %zux%zu for a %zux%zu grid",
		    fft->nx, fft->ny, g->nx, g->ny);
	memcpy(fft->real, g->z, rc_grid_size(g) * sizeof(double));
	rc_fft_forward(fft);
	*use = fft;
	return 0;
}

int
rc_spectral_derivs(const rc_grid *g, rc_fft *fft, double *hx, double *hy,
    double *lap, rc_err *err)
{
	rc_fft own, *f;
	size_t n = rc_grid_size(g), nxc;
	double complex *spec0;

	memset(&own, 0, sizeof(own));
	if (transform(g, fft, &own, &f, err) != 0)
		return -1;
	nxc = f->nxc;
	/* c2r destroys its input, so keep the height spectrum for each output. */
	if ((spec0 = fftw_alloc_complex(nxc * g->ny)) == NULL) {
		rc_fft_free(&own);
		return rc_seterr(err, "out of memory (asked for %zu bytes)",
		    nxc * g->ny * sizeof(double complex));
	}
	memcpy(spec0, f->spec, nxc * g->ny * sizeof(double complex));
	double *out[3] = { hx, hy, lap };
	for (int d = 0; d < 3; d++) {
		if (out[d] == NULL)
			continue;
		for (size_t j = 0; j < g->ny; j++) {
			double qy = rc_wavenumber(j, g->ny, g->ly);
			double dqy = rc_deriv_wavenumber(j, g->ny, g->ly);
			for (size_t i = 0; i < nxc; i++) {
				double qx = rc_wavenumber(i, g->nx, g->lx);
				double dqx = rc_deriv_wavenumber(i, g->nx, g->lx);
				double complex c = spec0[j * nxc + i] / (double)n;
				if (d == 0)
					c *= I * dqx;
				else if (d == 1)
					c *= I * dqy;
				else
					c *= -(qx * qx + qy * qy);
				f->spec[j * nxc + i] = c;
			}
		}
		rc_fft_backward(f);
		memcpy(out[d], f->real, n * sizeof(double));
	}
	fftw_free(spec0);
	rc_fft_free(&own);
	return 0;
}

int
rc_spectral_deriv(const rc_grid *g, rc_fft *fft, enum rc_deriv which,
    rc_err *err)
{
	rc_fft *f;
	double n = (double)rc_grid_size(g);

	if (fft == NULL)
		return rc_seterr(err, "internal: rc_spectral_deriv needs a plan");
	if (transform(g, fft, NULL, &f, err) != 0)
		return -1;
	for (size_t j = 0; j < g->ny; j++) {
		double qy = rc_wavenumber(j, g->ny, g->ly);
		double dqy = rc_deriv_wavenumber(j, g->ny, g->ly);
		for (size_t i = 0; i < f->nxc; i++) {
			double qx = rc_wavenumber(i, g->nx, g->lx);
			double complex factor;
			if (which == RC_DERIV_X)
				factor = I * rc_deriv_wavenumber(i, g->nx, g->lx);
			else if (which == RC_DERIV_Y)
				factor = I * dqy;
			else
				factor = -(qx * qx + qy * qy);
			f->spec[j * f->nxc + i] *= factor / n;
		}
	}
	rc_fft_backward(f);
	return 0;
}

int
rc_rms_gradient(const rc_grid *g, rc_fft *fft, double *gbar, rc_err *err)
{
	rc_fft own, *f;
	double sum = 0, n = (double)rc_grid_size(g);

	memset(&own, 0, sizeof(own));
	if (transform(g, fft, &own, &f, err) != 0)
		return -1;
	for (size_t j = 0; j < g->ny; j++) {
		double qy = rc_deriv_wavenumber(j, g->ny, g->ly);
		for (size_t i = 0; i < f->nxc; i++) {
			double qx = rc_deriv_wavenumber(i, g->nx, g->lx);
			double m = cabs(f->spec[j * f->nxc + i]);
			sum += rc_fft_weight(i, g->nx) * (qx * qx + qy * qy) * m * m;
		}
	}
	*gbar = sqrt(sum) / n;
	rc_fft_free(&own);
	return 0;
}

void
rc_mean_rms(const double *z, size_t n, double *mean, double *rms)
{
	double s = 0, s2 = 0, m;

	for (size_t i = 0; i < n; i++)
		s += z[i];
	m = s / (double)n;
	for (size_t i = 0; i < n; i++)
		s2 += (z[i] - m) * (z[i] - m);
	if (mean)
		*mean = m;
	if (rms)
		*rms = sqrt(s2 / (double)n);
}
