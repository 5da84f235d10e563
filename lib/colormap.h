/* SPDX-License-Identifier: GPL-3.0-or-later */
/* colormap.h - a perceptually uniform colormap, computed.
 *
 * A path through CIELAB (D65): lightness L* rises linearly from 18 to 92,
 * the hue angle turns from 290 deg (blue-violet) through blue, teal and
 * green to 100 deg (yellow), as viridis does, and the chroma grows from 38
 * to 78, reduced where needed (at fixed L* and hue) until the colour fits
 * the sRGB gamut.  Equal steps in t are equal steps in lightness, so the
 * map reads the same in grey scale and to colour-blind eyes.
 */
#ifndef RC_COLORMAP_H
#define RC_COLORMAP_H

#include <stdint.h>

/* The colour at t in [0, 1] (clamped) as sRGB components in [0, 1]. */
void rc_colormap_srgb(double t, double rgb[3]);
/* The same, rounded to 8 bits. */
void rc_colormap_rgb8(double t, uint8_t rgb[3]);
/* CIELAB of a colour given as sRGB components in [0, 1] (the inverse
 * conversion, for checking lightness). */
void rc_srgb_to_lab(const double rgb[3], double lab[3]);

/* Mask colours: 0 (no contact) white, 1 (contact) black; an overlay mask
 * is drawn in RC_OVERLAY_RGB with opacity RC_OVERLAY_ALPHA. */
#define RC_MASK0_RGB { 255, 255, 255 }
#define RC_MASK1_RGB { 0, 0, 0 }
#define RC_OVERLAY_RGB { 255, 32, 32 }
#define RC_OVERLAY_ALPHA 0.65
/* Log scale: values <= 0 (no pressure) are drawn black. */
#define RC_NONPOS_RGB { 0, 0, 0 }
/* Non-finite values are drawn mid grey. */
#define RC_NAN_RGB { 128, 128, 128 }

#endif
