# SPDX-License-Identifier: GPL-3.0-or-later
# Makefile - build, test, install and demo the rough-contact toolkit.
#   make                 library and tools into bin/
#   make check           all tests; ends with "N passed, N failed[, N skipped]"
#   make check SANITIZE=1  the same under AddressSanitizer + UBSan
#   make demo            the built-in default example
#   make bench           benchmarks (print figures, never fail on time)
#   make doc             doc/*.md regenerated from the benchmarks and tests
#   make install PREFIX=/usr/local

PREFIX  ?= /usr/local
VERSION  = $(shell sed -n 's/^\#define RC_VERSION "\(.*\)"/\1/p' tools/common.h)
CC      ?= cc
PKGS     = fftw3 gsl libpng libzip libxml-2.0 netcdf zlib yaml-0.1
OPTFLAGS ?= -O2 -g
CFLAGS  ?= $(OPTFLAGS)
WARN     = -Wall -Wextra -Wshadow -Wstrict-prototypes -Wmissing-prototypes
# -ffp-contract=off: a*b + c rounded twice, as ISO C and gcc's -std=c11
# do; clang (and gcc in GNU mode) would fuse it into an FMA where the
# target has one, and the rows' bits would depend on compiler and flags
STD      = -std=c11 -D_DEFAULT_SOURCE -D_POSIX_C_SOURCE=200809L -ffp-contract=off
PKG_CONFIG ?= pkg-config
PKG_CFLAGS := $(shell $(PKG_CONFIG) --cflags $(PKGS) 2>/dev/null)
# libnetcdf, libzip, libxml2 and libyaml are compiled against but loaded
# only when a file that needs them is read or written (lib/io_nc.c,
# lib/io_dl_internal.h say why): not linked; each soname from the shared
# library pkg-config points to.  The tests that make zips themselves link them.
PKGS_DLOPEN = netcdf libzip libxml-2.0 yaml-0.1
PKG_LIBS   := $(shell $(PKG_CONFIG) --libs $(filter-out $(PKGS_DLOPEN),$(PKGS)) 2>/dev/null)
DLOPEN_LIBS := $(shell $(PKG_CONFIG) --libs $(filter-out netcdf,$(PKGS_DLOPEN)) 2>/dev/null)
soname = $(shell objdump -p "$$($(PKG_CONFIG) --variable=libdir $(1) 2>/dev/null)/$(2).so" 2>/dev/null | awk '$$1 == "SONAME" { print $$2 }')
NETCDF_SONAME := $(call soname,netcdf,libnetcdf)
ZIP_SONAME := $(call soname,libzip,libzip)
XML_SONAME := $(call soname,libxml-2.0,libxml2)
YAML_SONAME := $(call soname,yaml-0.1,libyaml)
DLOPEN_CFLAGS = $(if $(NETCDF_SONAME),-DRC_NETCDF_SONAME='"$(NETCDF_SONAME)"') \
	$(if $(ZIP_SONAME),-DRC_ZIP_SONAME='"$(ZIP_SONAME)"') \
	$(if $(XML_SONAME),-DRC_XML_SONAME='"$(XML_SONAME)"') \
	$(if $(YAML_SONAME),-DRC_YAML_SONAME='"$(YAML_SONAME)"')

# Before compiling anything: every library must be found, else name the
# Debian packages to install (instead of a compiler error on fftw3.h).
# libfftw3_omp has no pkg-config file; the compiler looks for it.
# Test with e.g. make PKG_CONFIG=false, or make PKGS=nonexistent.
DEB_fftw3 = libfftw3-dev
DEB_fftw3_omp = libfftw3-dev
DEB_gsl = libgsl-dev
DEB_libpng = libpng-dev
DEB_libzip = libzip-dev
DEB_libxml-2.0 = libxml2-dev
DEB_netcdf = libnetcdf-dev
DEB_zlib = zlib1g-dev
DEB_yaml-0.1 = libyaml-dev
NODEP_GOALS = clean deps uninstall
ifneq ($(filter-out $(NODEP_GOALS),$(or $(MAKECMDGOALS),all)),)
HAVE_PKG_CONFIG := $(shell command -v $(PKG_CONFIG) >/dev/null 2>&1 && echo y)
HAVE_CC := $(shell command -v $(CC) >/dev/null 2>&1 && echo y)
MISSING := $(foreach p,$(PKGS),$(if $(shell $(PKG_CONFIG) --exists $(p) 2>/dev/null && echo y),,$(p)))
MISSING += $(if $(filter /%,$(shell $(CC) -print-file-name=libfftw3_omp.so 2>/dev/null)),,fftw3_omp)
MISSING := $(strip $(MISSING))
ifneq ($(MISSING)$(if $(HAVE_PKG_CONFIG),,n)$(if $(HAVE_CC),,n),)
MISSING_DEB = $(sort $(if $(HAVE_PKG_CONFIG),,pkg-config) \
	$(if $(HAVE_CC),,build-essential) \
	$(foreach p,$(MISSING),$(DEB_$(p))))
MISSING_UNKNOWN = $(strip $(foreach p,$(MISSING),$(if $(DEB_$(p)),,$(p))))
empty :=
indent := $(empty)    $(empty)
$(info roughcontact: not found: $(strip $(if $(HAVE_CC),,$(CC)) \
	$(if $(HAVE_PKG_CONFIG),,$(PKG_CONFIG)) $(MISSING)))
$(if $(MISSING_DEB),$(info roughcontact: install the Debian packages (as root, leave out sudo):))
$(if $(MISSING_DEB),$(info $(indent)sudo apt-get install -y $(MISSING_DEB)))
$(if $(MISSING_UNKNOWN),$(info roughcontact: no Debian package known for: $(MISSING_UNKNOWN)))
$(info roughcontact: all build and test dependencies at once: make deps (as root))
$(error missing build dependencies)
endif
endif
ALL_CFLAGS = $(STD) $(WARN) -fopenmp $(CFLAGS) $(SAN_FLAGS) $(LIB_DIRS:%=-I%) -Itools $(PKG_CFLAGS) \
	$(DLOPEN_CFLAGS)
LDLIBS   = -lfftw3_omp $(PKG_LIBS) -lm
ALL_LDFLAGS = -fopenmp $(SAN_FLAGS) $(LDFLAGS)

ifeq ($(SANITIZE),1)
SAN_FLAGS = -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
O   = build/san
BIN = build/san/bin
else
O   = build
BIN = bin
endif

# lib/ and its module folders (lib/solver: the contact solver; lib/elastic:
# its elastic operators); lib/mpi is the MPI build's
LIB_DIRS = lib lib/solver lib/elastic
LIB_SRC  = $(wildcard $(LIB_DIRS:%=%/*.c))
LIB_OBJ  = $(LIB_SRC:%.c=$(O)/%.o)
LIB      = $(O)/librc.a
TOOL_SHARED = tools/common.c tools/surfgen_opts.c tools/gfmd_opts.c \
	tools/gfmd_row.c
TOOL_SRC = $(filter-out $(TOOL_SHARED),$(wildcard tools/*.c))
TOOLS    = $(TOOL_SRC:tools/%.c=$(BIN)/%)
COMMON_OBJ = $(TOOL_SHARED:%.c=$(O)/%.o)
TEST_SRC = $(wildcard tests/test_*.c)
TESTS    = $(TEST_SRC:tests/%.c=$(O)/tests/%)
# free_cases: the closed-form free-boundary problems, also bench_free's;
# rough_cases: the rough surface and solver set-up, also bench_gfmd's
TESTLIB_OBJ = $(O)/tests/testlib.o $(O)/tests/free_cases.o \
	$(O)/tests/rough_cases.o
MAN1 = $(wildcard man/man1/*.1)
MAN3 = $(wildcard man/man3/*.3)
MAN5 = $(wildcard man/man5/*.5)
MAN7 = $(wildcard man/man7/*.7)
BENCH_SRC = $(wildcard bench/bench_*.c)
BENCHES  = $(BENCH_SRC:bench/%.c=$(O)/bench/%)

.PHONY: all check demo bench install uninstall clean deps accuracy \
	$(O)/roughcontact.pc
# Keep objects: they are intermediate files of the pattern rules.
.SECONDARY:
all: $(TOOLS)

$(O)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) -MMD -MP -c -o $@ $<

$(LIB): $(LIB_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(BIN)/%: $(O)/tools/%.o $(COMMON_OBJ) $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_LDFLAGS) -o $@ $^ $(LDLIBS)

$(O)/tests/test_%: $(O)/tests/test_%.o $(TESTLIB_OBJ) $(LIB)
	$(CC) $(ALL_LDFLAGS) -o $@ $^ $(LDLIBS) $(DLOPEN_LIBS)

$(O)/bench/bench_%: $(O)/bench/bench_%.o $(LIB)
	$(CC) $(ALL_LDFLAGS) -o $@ $^ $(LDLIBS)
$(O)/bench/bench_free: $(O)/bench/bench_free.o $(O)/tests/free_cases.o $(LIB)
	$(CC) $(ALL_LDFLAGS) -o $@ $^ $(LDLIBS)
$(O)/bench/bench_gfmd: $(O)/bench/bench_gfmd.o $(O)/tests/rough_cases.o $(LIB)
	$(CC) $(ALL_LDFLAGS) -o $@ $^ $(LDLIBS)

# make check: every test but the long validations of tests/long.txt (at
# most 5 minutes on 2 idle cores); make check-long: those (CI runs both)
check: $(TOOLS) $(TESTS)
	@sh tests/run.sh $(BIN) $(O)/tests quick
.PHONY: check-long
check-long: $(TOOLS) $(TESTS)
	@sh tests/run.sh $(BIN) $(O)/tests long

# the hard-case matrix (tests/e2e/hard.sh) on 4x and 8x finer grids; minutes
.PHONY: check-hard
check-hard: $(TOOLS)
	@sh tests/hard/hard-big.sh $(BIN)

bench: $(TOOLS) $(BENCHES)
	@for b in $(BENCHES); do echo "== $$b"; $$b || exit 1; done
	@for s in bench/*.sh; do [ -f "$$s" ] || continue; echo "== $$s"; RC_BIN=$(BIN) RC_BENCH_BIN=$(O)/bench sh $$s || exit 1; done

# make doc: doc/NAME.md from doc/NAME.md.in, each generated section the
# output of the benchmark or test its marker names (doc/gen.sh): the
# measured record the manual pages point to.  Runs them all, so not part
# of check: the full benchmarks (bench_gfmd up to 2048^2) ran for over
# half an hour on the shared 2-core test machine; DOC_QUICK=1 runs their
# small sizes (256^2 and 512^2; 512^2 and 1024^2 for the process and
# memory scripts).  tests/e2e/docs.sh checks the made documents.
DOC_IN = $(wildcard doc/*.md.in)
.PHONY: doc
doc: $(TOOLS) $(BENCHES) $(O)/bench/peakrss $(TESTS)
	@$(if $(DOC_QUICK),BENCH_QUICK=1 BENCH_PROCESS_SIZES="512 1024" BENCH_SIZES="512 1024") \
	    sh doc/gen.sh $(BIN) $(O)/bench $(O)/tests $(DOC_IN)

# peak RSS of a command (bench/bench_memory.sh)
bench: $(O)/bench/peakrss
$(O)/bench/peakrss: bench/peakrss.c
	@mkdir -p $(dir $@)
	$(CC) $(STD) $(WARN) $(CFLAGS) -o $@ bench/peakrss.c

# accuracy of a_r against wall time (bench/accuracy/README.md; FINE_REF=1
# for the 8192^2 reference)
accuracy: $(TOOLS)
	$(MAKE) -C bench/accuracy BIN=$(abspath $(BIN))

# the measured-data path over a folder of instrument files (bench/field.sh;
# not part of check: FIELD=DIR, a corpus the user has; MANIFEST=FILE)
.PHONY: field
field: $(TOOLS)
	@if [ -z "$(FIELD)" ]; then echo "make field: give the folder of instrument files: make field FIELD=DIR (a MANIFEST.tsv beside or in DIR is compared)" >&2; exit 2; fi
	@RC_BIN=$(BIN) sh bench/field.sh $(if $(MANIFEST),-m "$(MANIFEST)") "$(FIELD)"

demo: $(TOOLS)
	@RC_BIN=$(BIN) sh data/demo.sh

# The library is installed as libroughcontact.a with its public headers
# (every header of $(LIB_DIRS) but the *_internal.h and *_impl.h ones) under
# include/roughcontact/, an umbrella header roughcontact.h that includes
# them all, and roughcontact.pc for pkg-config.
PUB_HDR = $(filter-out %_internal.h %_impl.h,$(wildcard $(LIB_DIRS:%=%/*.h)))
LIBDIR  ?= $(PREFIX)/lib
INCDIR  ?= $(PREFIX)/include/roughcontact
PCDIR   ?= $(LIBDIR)/pkgconfig
$(O)/roughcontact.h: $(PUB_HDR)
	@mkdir -p $(dir $@)
	{ echo '/* roughcontact.h - every public header of the roughcontact library. */'; \
	  echo '#ifndef ROUGHCONTACT_H'; echo '#define ROUGHCONTACT_H'; \
	  for h in $(notdir $(PUB_HDR)); do echo "#include \"$$h\""; done; \
	  echo '#endif'; } > $@
$(O)/roughcontact.pc:
	@mkdir -p $(dir $@)
	{ echo 'prefix=$(PREFIX)'; echo 'libdir=$(LIBDIR)'; \
	  echo 'includedir=$(PREFIX)/include'; echo; \
	  echo 'Name: roughcontact'; \
	  echo 'Description: contact mechanics of rough surfaces (GFMD, statistics, formats)'; \
	  echo 'Version: $(VERSION)'; \
	  echo 'Requires: $(filter-out $(PKGS_DLOPEN),$(PKGS))'; \
	  echo 'Cflags: -I$${includedir} -fopenmp'; \
	  echo 'Libs: -L$${libdir} -lroughcontact -lfftw3_omp -fopenmp -lm'; } > $@

install: $(TOOLS) $(LIB) $(O)/roughcontact.h $(O)/roughcontact.pc
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1 \
	    $(DESTDIR)$(PREFIX)/share/man/man3 \
	    $(DESTDIR)$(PREFIX)/share/man/man5 $(DESTDIR)$(PREFIX)/share/man/man7 \
	    $(DESTDIR)$(LIBDIR) $(DESTDIR)$(INCDIR) $(DESTDIR)$(PCDIR)
	install -m 755 $(TOOLS) $(DESTDIR)$(PREFIX)/bin
	install -m 644 $(LIB) $(DESTDIR)$(LIBDIR)/libroughcontact.a
	install -m 644 $(PUB_HDR) $(O)/roughcontact.h $(DESTDIR)$(INCDIR)
	install -m 644 $(O)/roughcontact.pc $(DESTDIR)$(PCDIR)
	install -m 644 $(MAN1) $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 644 $(MAN3) $(DESTDIR)$(PREFIX)/share/man/man3
	install -m 644 $(MAN5) $(DESTDIR)$(PREFIX)/share/man/man5
	install -m 644 $(MAN7) $(DESTDIR)$(PREFIX)/share/man/man7

uninstall:
	rm -f $(TOOLS:$(BIN)/%=$(DESTDIR)$(PREFIX)/bin/%) \
	    $(DESTDIR)$(LIBDIR)/libroughcontact.a $(DESTDIR)$(PCDIR)/roughcontact.pc \
	    $(MAN1:man/%=$(DESTDIR)$(PREFIX)/share/man/%) \
	    $(MAN3:man/%=$(DESTDIR)$(PREFIX)/share/man/%) \
	    $(MAN5:man/%=$(DESTDIR)$(PREFIX)/share/man/%) \
	    $(MAN7:man/%=$(DESTDIR)$(PREFIX)/share/man/%)
	rm -rf $(DESTDIR)$(INCDIR)

# Debian packages: deps.txt to build, test and run the demo (README's
# install line), deps-optional.txt for the tests that skip without them,
# check-mpi and valgrind; .ci/run installs the same two lists.
deps:
	apt-get update && apt-get install -y --no-install-recommends \
	    $$(cat deps.txt deps-optional.txt)

clean:
	rm -rf build bin

# make fuzz: build the libFuzzer harnesses of tests/fuzz with clang and run
# each for FUZZ_SECONDS (default 60); crashes become regression files under
# tests/data/fuzz/<harness>/ (replayed by test_fuzz_replay in make check).
FUZZ_SECONDS ?= 60
FUZZ_CC  ?= clang
FUZZ_CFLAGS = -g -O1 -fsanitize=fuzzer,address,undefined \
	-fno-sanitize-recover=undefined $(STD) $(LIB_DIRS:%=-I%) $(PKG_CFLAGS) $(DLOPEN_CFLAGS)
FUZZ_READ_SRC = lib/io.c lib/io_shared.c lib/io_surf.c lib/io_npy.c lib/io_gsf.c lib/io_txt.c lib/io_txt_head.c \
	lib/io_chan.c lib/io_gwy.c lib/io_x3p.c lib/io_nc.c lib/io_h5check.c lib/io_sdf.c \
	lib/io_gwyddion.c lib/io_decode.c lib/io_zip.c lib/io_xlsx.c lib/io_ce.c lib/md5.c lib/grid.c lib/rc_err.c lib/atomic.c lib/units.c
# what those call: libzip/libxml2/libyaml loaded at run time (io_dl.c),
# grids' values on huge pages (rc_grid_values -> fft.c's rc_fft_huge)
FUZZ_READ_SRC += lib/io_dl.c lib/fft.c lib/clock.c lib/threads.c
# other vendors' formats read here (lib/io_internal.h)
FUZZ_READ_SRC += lib/io_tmd.c lib/io_opdx.c lib/io_nms.c lib/io_mnt.c
FUZZ_ROWS_SRC = lib/table_read.c lib/rc_err.c
.PHONY: fuzz
fuzz: build/fuzz/fuzz_read build/fuzz/fuzz_rows $(TOOLS)
	@sh tests/fuzz/run.sh build/fuzz $(FUZZ_SECONDS) $(BIN)
build/fuzz/fuzz_read: tests/fuzz/fuzz_read.c $(FUZZ_READ_SRC) lib/io.h lib/io_internal.h lib/units.h
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -o $@ tests/fuzz/fuzz_read.c $(FUZZ_READ_SRC) $(PKG_LIBS) -lm
build/fuzz/fuzz_rows: tests/fuzz/fuzz_rows.c $(FUZZ_ROWS_SRC) lib/table_read.h
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -o $@ tests/fuzz/fuzz_rows.c $(FUZZ_ROWS_SRC) -lm

# make MPI=1: also the MPI builds of surfgen and gfmd-solve (lib/mpi/,
# tools/mpi/; OpenMPI and FFTW-MPI: apt-get install openmpi-bin libopenmpi-dev
# libfftw3-mpi-dev) in build/mpi/bin/: the serial library as it is plus
# lib/mpi/*.o, whose distributed elastic operator (lib/mpi/delastic.c)
# implements the seam of lib/elastic/elastic.h through which the serial solver
# sums over all ranks; no object is built twice.  make check-mpi tests them
# against the serial tools with 1, 2 and 3 ranks (tests/mpi/check.sh).
MPICC ?= mpicc
MPI_O = build/mpi
MPI_BIN = build/mpi/bin
MPI_TOOLS = $(MPI_BIN)/surfgen $(MPI_BIN)/gfmd-solve
MPI_LIB_OBJ = $(patsubst %.c,$(MPI_O)/%.o,$(wildcard lib/mpi/*.c))
MPI_TOOL_OBJ = $(MPI_O)/tools/mpi/mpitool.o
.PHONY: check-mpi
check-mpi:
	@$(MAKE) -s MPI=1 $(TOOLS) $(MPI_TOOLS)
	@sh tests/mpi/check.sh $(BIN) $(MPI_BIN)
ifeq ($(MPI),1)
all: $(MPI_TOOLS)
$(MPI_O)/%.o: %.c
	@mkdir -p $(dir $@)
	$(MPICC) $(ALL_CFLAGS) -MMD -MP -c -o $@ $<
$(MPI_BIN)/%: $(MPI_O)/tools/mpi/%.o $(MPI_TOOL_OBJ) $(MPI_LIB_OBJ) $(COMMON_OBJ) $(LIB)
	@mkdir -p $(dir $@)
	$(MPICC) $(ALL_LDFLAGS) -o $@ $^ -lfftw3_mpi $(LDLIBS)
-include $(MPI_LIB_OBJ:.o=.d) $(MPI_TOOL_OBJ:.o=.d) $(MPI_TOOLS:$(MPI_BIN)/%=$(MPI_O)/tools/mpi/%.d)
endif

# the test helpers' and benchmarks' too: a stale free_cases.o keeps an
# old rc_solver_opts layout
-include $(LIB_OBJ:.o=.d) $(COMMON_OBJ:.o=.d) $(TEST_SRC:%.c=$(O)/%.d) $(TOOL_SRC:%.c=$(O)/%.d) \
	$(TESTLIB_OBJ:.o=.d) $(BENCH_SRC:%.c=$(O)/%.d)
