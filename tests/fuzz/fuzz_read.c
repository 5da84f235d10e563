/* fuzz_read.c - libFuzzer harness for every grid reader.
 *
 * The input goes through the format detector twice: from memory (a stream
 * of unknown size, as a pipe) and from a regular file (whose size the
 * reader checks before allocating).  Any crash, leak, sanitizer report,
 * hang or allocation beyond -malloc_limit_mb is a bug.  Not part of the
 * default build; run from the top directory:
 *
 *   clang -g -O1 -fsanitize=fuzzer,address,undefined -std=c11 \
 *       -D_DEFAULT_SOURCE -D_POSIX_C_SOURCE=200809L -Ilib \
 *       tests/fuzz/fuzz_read.c lib/io.c lib/io_surf.c lib/io_npy.c \
 *       lib/io_gsf.c lib/io_txt.c lib/grid.c lib/rc_err.c lib/atomic.c \
 *       $(pkg-config --cflags --libs fftw3) -lm -o build/fuzz_read
 *   mkdir -p build/fuzz-corpus && cp tests/data/io_small.* build/fuzz-corpus
 *   build/fuzz_read -max_total_time=60 -malloc_limit_mb=256 \
 *       -max_len=4096 build/fuzz-corpus
 *
 * A crashing input is written to crash-<hash>; keep it under tests/data
 * as a regression file.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	rc_read_opts o = { 2, 3, 1, 0 };
	char path[] = "/tmp/fuzz_read.XXXXXX";
	rc_err err;
	FILE *fp;
	int fd;

	if (size == 0)
		return 0;
	if ((fp = fmemopen((void *)data, size, "rb")) != NULL) {
		rc_grid_free(rc_grid_read_stream(fp, &o, &err));
		fclose(fp);
	}
	if ((fd = mkstemp(path)) >= 0) {
		if (write(fd, data, size) == (ssize_t)size)
			rc_grid_free(rc_grid_read(path, NULL, &err));
		close(fd);
		unlink(path);
	}
	return 0;
}
