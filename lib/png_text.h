/* SPDX-License-Identifier: GPL-3.0-or-later */
/* png_text.h - a tiny bitmap font for the labels of PNG previews.
 *
 * Glyphs are 5 pixels wide and 7 tall, drawn at an integer scale (each
 * font pixel a scale x scale block), one blank column between characters.
 * The set is what the previews write: digits, lower-case letters (upper
 * case is drawn as lower case but for C, D, H and L), space and . - + = * _ ( ) / : , % ^ and
 * the micro sign (UTF-8 C2 B5, one character); any other byte is drawn
 * as an empty box.
 */
#ifndef RC_PNG_TEXT_H
#define RC_PNG_TEXT_H

#include <stddef.h>
#include <stdint.h>

#define RC_FONT_W 5
#define RC_FONT_H 7
#define RC_FONT_ADVANCE (RC_FONT_W + 1)

/* The 7 rows of c's glyph, top first; bit 4 of a row is its left pixel. */
const uint8_t *rc_font_glyph(char c);
/* Width in pixels of s drawn at scale (no trailing blank column). */
size_t rc_text_width(const char *s, int scale);
/* Draw s with its top-left corner at (x, y) into an RGB image of width by
 * height pixels, in colour; what falls outside the image is clipped. */
void rc_text_draw(uint8_t *rgb, size_t width, size_t height, long x, long y,
    const char *s, int scale, const uint8_t colour[3]);

#endif
