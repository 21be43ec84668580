# ptpgen: build, test, install and benchmark. `make` builds ./ptpgen with $(CC) (gcc or clang).
CC ?= cc
CFLAGS ?= -O2
# Static linking halves process start-up, a third of a small run (make LDFLAGS= to link dynamically).
LDFLAGS ?= -static
PREFIX ?= /usr/local
STD = -std=c11 -Wall -Wextra -Werror -pedantic
B = build/$(notdir $(CC))

GEN_SRC = $(sort $(wildcard gen/*.c))
GEN_HDR = $(sort $(wildcard gen/*.h))
TEMPLATES = $(sort $(wildcard templates/*/*))
# The library the tests link: the generator without main, and the embedded templates.
LIB_SRC = $(filter-out gen/main.c,$(GEN_SRC)) $(B)/templates.c
TESTS = $(patsubst tests/%.c,%,$(sort $(wildcard tests/test_*.c)))

all: ptpgen

# ./ptpgen is a copy of the binary built by the compiler asked for, so that
# `make CC=clang` after `make` really switches compilers.
ptpgen: $(B)/ptpgen FORCE
	@cmp -s $< $@ || cp $< $@

$(B)/ptpgen: $(GEN_SRC) $(GEN_HDR) $(B)/templates.c Makefile
	$(CC) $(STD) $(CFLAGS) $(LDFLAGS) -Igen -o $@ $(GEN_SRC) $(B)/templates.c

# The templates are compiled in, so an installed ptpgen works from any directory.
$(B)/templates.c: $(TEMPLATES) $(B)/embed
	$(B)/embed $(TEMPLATES) >$@.tmp && mv $@.tmp $@

$(B)/embed: gen/embed/embed.c
	@mkdir -p $(B)
	$(CC) $(STD) -O1 -o $@ $<

$(B)/test_%: tests/test_%.c tests/check.h tests/kref.c tests/kref.h $(LIB_SRC) $(GEN_HDR) Makefile
	$(CC) $(STD) $(CFLAGS) -Igen -Itests -o $@ $< tests/kref.c $(LIB_SRC) -lm

# The generator library and kref as an archive, for test programs built around emitted headers.
$(B)/libptptest.a: $(LIB_SRC) $(GEN_HDR) tests/kref.c tests/kref.h tests/check.h Makefile
	rm -rf $(B)/lib && mkdir -p $(B)/lib
	cd $(B)/lib && $(CC) $(STD) $(CFLAGS) -I$(CURDIR)/gen -I$(CURDIR)/tests -c $(addprefix $(CURDIR)/,$(LIB_SRC) tests/kref.c)
	ar rcs $@ $(B)/lib/*.o

# The hosts that run emitted kernels: OpenCL through PoCL, Vulkan (GLSL, HLSL) on lavapipe.
$(B)/host_opencl: tests/host_opencl.c tests/check.h tests/kref.c tests/kref.h $(LIB_SRC) $(GEN_HDR) Makefile
	$(CC) $(STD) $(CFLAGS) -Igen -Itests -o $@ $< tests/kref.c $(LIB_SRC) -lOpenCL -lm

$(B)/host_vulkan: tests/host_vulkan.c tests/check.h tests/kref.c tests/kref.h $(LIB_SRC) $(GEN_HDR) Makefile
	$(CC) $(STD) $(CFLAGS) -Igen -Itests -o $@ $< tests/kref.c $(LIB_SRC) -lvulkan -lm

# Everything one compiler builds for the tests.
build-tests: $(B)/ptpgen $(addprefix $(B)/,$(TESTS))

test:
	@bash tests/run.sh

install: ptpgen
	install -d $(DESTDIR)$(PREFIX)/bin
	install -m 755 ptpgen $(DESTDIR)$(PREFIX)/bin/ptpgen

bench-gen: $(B)/bench_gen ptpgen
	$(B)/bench_gen ./ptpgen

$(B)/bench_gen: bench/bench_gen.c
	@mkdir -p $(B)
	$(CC) $(STD) $(CFLAGS) -o $@ $<

# Fuzzing verify's parsers with libFuzzer (clang): `make fuzz FUZZ_SECONDS=600`. New inputs
# collect in build/fuzz/corpus; copy an input that fails into tests/fuzz/regressions/, which the
# tests replay (with tests/fuzz/verify/, the seeds) under AddressSanitizer and UBSan.
FUZZ_SECONDS ?= 300
SAN = -g -O1 -fsanitize=address,undefined -fno-sanitize-recover=all

fuzz:
	@$(MAKE) -s CC=clang build/clang/templates.c
	@mkdir -p build/fuzz/corpus
	clang $(STD) $(SAN) -fsanitize=fuzzer -Igen -o build/fuzz/fuzz_verify tests/fuzz_verify.c \
	    $(filter-out gen/main.c,$(GEN_SRC)) build/clang/templates.c -lm
	build/fuzz/fuzz_verify -max_total_time=$(FUZZ_SECONDS) -max_len=65536 -timeout=10 \
	    build/fuzz/corpus tests/fuzz/verify tests/fuzz/regressions

$(B)/replay_verify: tests/fuzz_verify.c $(LIB_SRC) $(GEN_HDR) Makefile
	$(CC) $(STD) $(SAN) -DFUZZ_REPLAY -Igen -o $@ $< $(LIB_SRC) -lm

# The vendored sources: every kernel target, json and table for common degrees (clip space,
# the default schedule). `make out` regenerates out/; the tests regenerate into a temporary
# OUTDIR with the gcc and the clang build and require identical bytes.
OUT_DEGREES = 1x1 2x2 3x3 4x4 1x3 3x1 2x3 3x2
OUT_FILES = c:.h glsl:.comp hlsl:.hlsl opencl:.cl cuda:.cu json:.json table:_table.h
OUTDIR ?= out
PTPGEN_BIN ?= ./ptpgen

out: ptpgen
	@for d in $(OUT_DEGREES); do \
	    mkdir -p $(OUTDIR)/$$d || exit 1; \
	    for te in $(OUT_FILES); do \
	        $(PTPGEN_BIN) --degree $$d --target $${te%%:*} -o $(OUTDIR)/$$d/ptp_$$d$${te#*:} || exit 1; \
	    done; \
	done

clean:
	rm -rf build ptpgen

FORCE:
.PHONY: all test install bench-gen build-tests out fuzz clean FORCE
