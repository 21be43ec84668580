# ptpgen: build, test, install and benchmark. `make` builds ./ptpgen with $(CC) (gcc or clang).
# Objects go to build/<compiler>/; `make B=dir` builds in another folder. `make install PREFIX=...`.
CC ?= cc
CFLAGS ?= -O2
# Static linking halves process start-up, a third of a small run (make LDFLAGS= to link dynamically).
LDFLAGS ?= -static
PREFIX ?= /usr/local
STD = -std=c11 -Wall -Wextra -Werror -pedantic
B = build/$(notdir $(CC))

# The generator's layers (gen/README.md); gen/embed is a build tool, not part of ptpgen.
GEN_LAYERS = core plan emit tools cli
GEN_SRC = $(sort $(foreach l,$(GEN_LAYERS),$(wildcard gen/$(l)/*.c)))
GEN_HDR = $(sort $(foreach l,$(GEN_LAYERS),$(wildcard gen/$(l)/*.h)))
TEMPLATES = $(sort $(wildcard templates/*/*))
# The generator without main, and the embedded templates (the fuzzers compile them with sanitizers).
LIB_SRC = $(filter-out gen/cli/main.c,$(GEN_SRC)) $(B)/templates.c
# Each source compiles once per compiler into $(B)/obj/; ptpgen, the tests and the hosts link the
# objects (make -j compiles them in parallel).
GEN_OBJ = $(patsubst %.c,$(B)/obj/%.o,$(GEN_SRC)) $(B)/obj/templates.o
# The library the tests and the hosts link: the generator without main, and kref.
LIB_OBJ = $(filter-out $(B)/obj/gen/cli/main.o,$(GEN_OBJ)) $(B)/obj/tests/kref.o \
    $(B)/obj/bench/bezfile.o
TESTS = $(patsubst tests/%.c,%,$(sort $(wildcard tests/test_*.c)))

all: ptpgen

# ./ptpgen is a copy of the binary built by the compiler asked for, so that
# `make CC=clang` after `make` really switches compilers.
ptpgen: $(B)/ptpgen FORCE
	@cmp -s $< $@ || cp $< $@

# Where a static link fails (no static libc), ptpgen is linked again without -static.
$(B)/ptpgen: $(GEN_OBJ)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $(GEN_OBJ) || \
	    { echo "ptpgen: the static link failed; linking dynamically" >&2; \
	      $(CC) $(CFLAGS) $(filter-out -static,$(LDFLAGS)) -o $@ $(GEN_OBJ); }

$(B)/obj/gen/%.o: gen/%.c $(GEN_HDR) Makefile
	@mkdir -p $(@D)
	$(CC) $(STD) $(CFLAGS) -Igen -c -o $@ $<

$(B)/obj/tests/kref.o: tests/kref.c tests/kref.h tests/check.h bench/bezfile.h $(GEN_HDR) Makefile
	@mkdir -p $(@D)
	$(CC) $(STD) $(CFLAGS) -Igen -Itests -Ibench -c -o $@ $<

# The BEZ reader of the tests and benchmarks.
$(B)/obj/bench/bezfile.o: bench/bezfile.c bench/bezfile.h Makefile
	@mkdir -p $(@D)
	$(CC) $(STD) $(CFLAGS) -c -o $@ $<

# The models: models/ holds the Utah teapot set; build/models/knot.bez (bench/mkmodel.c, 2,880
# bicubic patches) stands in for a large model, and build/models/far.bez (mkmodel --far, 4,096
# small patches far from the origin) is cullrate's test of absolute against local coordinates.
# MODELS=DIR adds a folder of .bez files (or, for `make figures`, picks BigGuy and the teapot
# from it), e.g. MODELS=../shared/models. The former CULLRATE_MODELS=DIR and FIGURES_MODELS=DIR
# set it too.
MODELS ?= $(or $(CULLRATE_MODELS),$(FIGURES_MODELS))
KNOT = build/models/knot.bez
FAR = build/models/far.bez
models: $(KNOT) $(FAR)
$(B)/mkmodel: bench/mkmodel.c
	@mkdir -p $(@D)
	$(CC) $(STD) $(CFLAGS) -o $@ $< -lm
$(KNOT): bench/mkmodel.c | $(B)/mkmodel
	@mkdir -p $(@D)
	$(B)/mkmodel $@.tmp && mv $@.tmp $@
$(FAR): bench/mkmodel.c | $(B)/mkmodel
	@mkdir -p $(@D)
	$(B)/mkmodel --far $@.tmp && mv $@.tmp $@

$(B)/obj/templates.o: $(B)/templates.c gen/emit/template.h Makefile
	@mkdir -p $(@D)
	$(CC) $(STD) $(CFLAGS) -Igen -c -o $@ $<

# The templates are compiled in, so an installed ptpgen works from any directory.
$(B)/templates.c: $(TEMPLATES) $(B)/embed
	$(B)/embed $(TEMPLATES) >$@.tmp && mv $@.tmp $@

$(B)/embed: gen/embed/embed.c
	@mkdir -p $(B)
	$(CC) $(STD) -O1 -o $@ $<

$(B)/test_%: tests/test_%.c tests/check.h tests/float_widen.h tests/kref.h $(GEN_HDR) $(B)/libptptest.a Makefile
	$(CC) $(STD) $(CFLAGS) -Igen -Itests -o $@ $< $(B)/libptptest.a -lm

# The generator library and kref as an archive: the tests, the hosts and test programs built
# around emitted headers link it.
$(B)/libptptest.a: $(LIB_OBJ)
	rm -f $@ && ar rcs $@ $(LIB_OBJ)

# The hosts that run emitted kernels: OpenCL through PoCL, Vulkan (GLSL, HLSL) on lavapipe.
$(B)/host_opencl: tests/host_opencl.c tests/check.h tests/kref.h $(GEN_HDR) $(B)/libptptest.a Makefile
	$(CC) $(STD) $(CFLAGS) -Igen -Itests -o $@ $< $(B)/libptptest.a -lOpenCL -lm

$(B)/host_vulkan: tests/host_vulkan.c tests/check.h tests/host_run.c tests/host_run.h tests/kref.h \
    tests/vk_result.h $(GEN_HDR) $(B)/libptptest.a Makefile
	$(CC) $(STD) $(CFLAGS) -Igen -Itests -o $@ $< tests/host_run.c $(B)/libptptest.a -lvulkan -lm

# The WGSL host links wgpu-native (WebGPU's C API), from the wheel of the PyPI package wgpu that
# tests/deps.sh installs into build/venv; WGPU_DIR holds webgpu.h, wgpu.h and the library.
WGPU_DIR ?= $(firstword $(wildcard $(CURDIR)/build/venv/lib/python3*/site-packages/wgpu/resources))

$(B)/host_wgpu: tests/host_wgpu.c tests/check.h tests/host_run.c tests/host_run.h tests/kref.h $(GEN_HDR) \
    $(B)/libptptest.a Makefile
	@test -n "$(WGPU_DIR)" || { echo "host_wgpu: no wgpu-native (WGPU_DIR): run tests/deps.sh's ptp_ensure_wgpu" >&2; exit 1; }
	$(CC) $(STD) $(CFLAGS) -Igen -Itests -isystem $(WGPU_DIR) -o $@ $< tests/host_run.c \
	    $(B)/libptptest.a -L$(WGPU_DIR) -l:libwgpu_native-release.so -Wl,-rpath,$(WGPU_DIR) -lm

# Everything one compiler builds for the tests.
build-tests: $(B)/ptpgen $(addprefix $(B)/,$(TESTS)) $(KNOT) $(FAR)

test:
	@bash tests/run.sh

install: ptpgen
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 755 ptpgen $(DESTDIR)$(PREFIX)/bin/ptpgen
	install -m 644 docs/ptpgen.1 $(DESTDIR)$(PREFIX)/share/man/man1/ptpgen.1

bench-gen: $(B)/bench_gen ptpgen
	$(B)/bench_gen ./ptpgen

$(B)/bench_gen: bench/bench_gen.c
	@mkdir -p $(B)
	$(CC) $(STD) $(CFLAGS) -o $@ $<

# `make bench`: culling throughput on this machine (bench/run_bench.sh): the paper's loop and the
# emitted C header's paths per bidegree on one core and on all cores, against a peak it measures;
# the OpenCL kernels on PoCL (lanes too), the GLSL kernel on lavapipe and the WGSL kernel on wgpu-native (the
# test hosts' --bench); ptpgen's own time. The hosts are built when their libraries are there; a missing one makes its rows unavailable.
BENCH_DEGREES = 2x2 3x3 4x4
BENCH_CFLAGS = -O3 -march=native
# $(CC) by default; make bench BENCH_CC=clang to compare (gcc runs the header's GNU C vectors,
# clang its own vectorization of the loop).
BENCH_CC ?= $(CC)

# Variants of the bicubic header whose batch path is timed too: --refine 3, --certified, both,
# --basis bspline (B-spline input: the conversion included) and --coordinates absolute (the
# points as given: what the patch-local frame costs).
BENCH_VARIANTS = refine3 certified certified_refine3 bspline absolute

bench: ptpgen $(B)/bench/peak $(addprefix $(B)/bench/bench_cull_,$(BENCH_DEGREES)) \
    $(addprefix $(B)/bench/bench_cull_3x3_,$(BENCH_VARIANTS)) $(B)/bench/bench_tri
	@$(MAKE) -s -k $(B)/host_opencl $(B)/host_vulkan $(B)/host_wgpu >$(B)/bench/hosts.log 2>&1 || true
	@bash bench/run_bench.sh $(B) $(BENCH_CC) "$(BENCH_CFLAGS)" $(BENCH_DEGREES)

# `make bench-tri`: only the triangle rows of `make bench` (bench/bench_tri.c): the degree-1 mesh
# path against the facet-normal and projected signed-area tests on one indexed mesh, with their
# bandwidth bounds, and PN-triangle against bicubic patches. BENCH_TRI_ARGS="--grid NU NV --reps N".
BENCH_TRI_ARGS ?=
bench-tri: $(B)/bench/bench_tri
	@$(B)/bench/bench_tri $(BENCH_TRI_ARGS)

# `make bench-paired`: the bicubic batch path of the default header against --coordinates absolute
# (what the patch-local frame costs) and --certified, in PAIRED_ROUNDS alternating rounds on CPU
# PAIRED_CPU (bench/paired.sh; by default the last CPU make may run on): each build's median time
# ratio to the default's, with a 95% interval.
PAIRED_ROUNDS ?= 41
PAIRED_CPU ?= last
bench-paired: $(B)/bench/bench_cull_3x3 $(B)/bench/bench_cull_3x3_absolute \
    $(B)/bench/bench_cull_3x3_certified
	@bash bench/paired.sh $(PAIRED_ROUNDS) $(PAIRED_CPU) local=$(B)/bench/bench_cull_3x3 \
	    absolute=$(B)/bench/bench_cull_3x3_absolute certified=$(B)/bench/bench_cull_3x3_certified

# The benchmark's compiler and flags: a change rebuilds the benchmarks.
$(B)/bench/cc.txt: FORCE
	@mkdir -p $(@D)
	@echo '$(BENCH_CC) $(BENCH_CFLAGS)' | cmp -s - $@ || echo '$(BENCH_CC) $(BENCH_CFLAGS)' >$@

$(B)/bench/ptp_%.h: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree $* --target c --space clip --rule strict --prefix ptp_$*_ -o $@

$(B)/bench/bench_cull_%: bench/bench_cull.c $(B)/bench/ptp_%.h Makefile $(B)/bench/cc.txt
	$(BENCH_CC) $(STD) $(BENCH_CFLAGS) -D_GNU_SOURCE -include $(B)/bench/ptp_$*.h \
	    -DPTP_$(subst x,X,$*)_IMPLEMENTATION -DPFX=ptp_$*_ -DUPFX=PTP_$(subst x,X,$*)_ \
	    -DDEGREE='"$*"' -o $@ $< -lm -pthread

$(B)/bench/ptp_3x3_refine3.h: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target c --refine 3 --prefix ptp_3x3_ -o $@

$(B)/bench/ptp_3x3_certified.h: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target c --certified --prefix ptp_3x3_ -o $@

$(B)/bench/ptp_3x3_certified_refine3.h: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target c --certified --refine 3 --prefix ptp_3x3_ -o $@

$(B)/bench/ptp_3x3_bspline.h: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target c --basis bspline --prefix ptp_3x3_ -o $@

$(B)/bench/ptp_3x3_absolute.h: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target c --coordinates absolute --prefix ptp_3x3_ -o $@

$(B)/bench/bench_cull_3x3_%: bench/bench_cull.c $(B)/bench/ptp_3x3_%.h Makefile $(B)/bench/cc.txt
	$(BENCH_CC) $(STD) $(BENCH_CFLAGS) -D_GNU_SOURCE -include $(B)/bench/ptp_3x3_$*.h \
	    -DPTP_3X3_IMPLEMENTATION -DPFX=ptp_3x3_ -DUPFX=PTP_3X3_ -DDEGREE='"3x3"' \
	    -DVARIANT='"$(subst _, ,$(subst absolute,--coordinates absolute,$(subst bspline,--basis bspline,$(subst refine,--refine ,$(subst certified,--certified,$*)))))"' \
	    -o $@ $< -lm -pthread

# The triangle benchmark's headers: degree 1 in world (ptp_tri1w_) and clip space, the cubic
# triangle (PN triangles) and the bicubic patch, all in one program.
$(B)/bench/ptp_tri1w.h: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --domain triangle --degree 1 --target c --space world --rule strict --prefix ptp_tri1w_ -o $@

$(B)/bench/ptp_tri%.h: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --domain triangle --degree $* --target c --space clip --rule strict --prefix ptp_tri$*_ -o $@

BENCH_TRI_HDR = $(addprefix $(B)/bench/ptp_,tri1w.h tri1.h tri3.h 3x3.h)
$(B)/bench/bench_tri: bench/bench_tri.c $(BENCH_TRI_HDR) Makefile $(B)/bench/cc.txt
	$(BENCH_CC) $(STD) $(BENCH_CFLAGS) -D_GNU_SOURCE $(addprefix -include ,$(BENCH_TRI_HDR)) \
	    -DPTP_TRI1W_IMPLEMENTATION -DPTP_TRI1_IMPLEMENTATION -DPTP_TRI3_IMPLEMENTATION \
	    -DPTP_3X3_IMPLEMENTATION -o $@ $< -lm

# The peak: FMA and add chains, with a * b + c contracted into FMAs.
$(B)/bench/peak: bench/peak.c Makefile $(B)/bench/cc.txt
	@mkdir -p $(@D)
	$(BENCH_CC) $(STD) $(BENCH_CFLAGS) -ffp-contract=fast -o $@ $< -pthread

# `make cert-look`: how often the certified bicubic C header leaves a patch to its second look in
# double, and how many it culls, with patch-local and absolute coordinates, world and clip space
# (bench/cert_look.c), on the knot, the far model and MODELS=dir's .bez files. CERT_LOOK_ARGS="--eyes N".
CERT_LOOK_ARGS ?=
CL_HDR = $(addprefix $(B)/bench/cl_,$(addsuffix .h,wl wa cl ca))
cert-look: $(B)/bench/cert_look $(KNOT) $(FAR)
	@$(B)/bench/cert_look $(CERT_LOOK_ARGS) $(KNOT) $(FAR) $(if $(MODELS),$(wildcard $(MODELS)/*.bez))
$(B)/bench/cl_%.h: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target c --certified $(if $(filter w%,$*),--space world) \
	    $(if $(filter %a,$*),--coordinates absolute) --prefix cl_$*_ -o $@
$(B)/bench/cert_look: bench/cert_look.c $(CL_HDR) $(B)/obj/bench/bezfile.o Makefile $(B)/bench/cc.txt
	$(BENCH_CC) $(STD) $(BENCH_CFLAGS) -Ibench $(addprefix -include ,$(CL_HDR)) -DCL_WL_IMPLEMENTATION \
	    -DCL_WA_IMPLEMENTATION -DCL_CL_IMPLEMENTATION -DCL_CA_IMPLEMENTATION -o $@ $< \
	    $(B)/obj/bench/bezfile.o -lm

.SECONDARY: $(addprefix $(B)/bench/ptp_,$(addsuffix .h,$(BENCH_DEGREES))) \
    $(addprefix $(B)/bench/ptp_3x3_,$(addsuffix .h,$(BENCH_VARIANTS))) $(BENCH_TRI_HDR) $(CL_HDR)
.PHONY: bench bench-tri bench-paired cert-look

# `make render`: build/render, ptpgen's clip-space GLSL kernels culling bicubic patches in a
# Vulkan tessellation pipeline (bench/render/, README "Rendering"). Every shader, ptpgen's
# kernels among them, is compiled to SPIR-V by glslangValidator and into the binary.
RB = $(B)/render
RENDER_SRC = $(sort $(wildcard bench/render/*.c)) bench/cones.c bench/bezfile.c
RENDER_HDR = $(wildcard bench/render/*.h) bench/cones.h bench/bezfile.h bench/vec3.h \
    tests/vk_result.h
RENDER_SHADERS = xform:xform.comp cone:cone.comp vert:patch.vert tesc:patch.tesc \
    tese:patch.tese frag:shade.frag
RENDER_SPV = $(foreach s,$(RENDER_SHADERS) ptp ptp_cert ptp_table tesc_ptp tesc_ptp_cert,$(RB)/spv_$(firstword $(subst :, ,$(s))).h)

render: build/render

# build/render is a copy of the binary of the compiler asked for (as ./ptpgen is).
build/render: $(RB)/render FORCE
	@cmp -s $< $@ || cp $< $@

$(RB)/render: $(RENDER_SRC) $(RENDER_HDR) $(RENDER_SPV) $(RB)/ptp_groups.h Makefile
	$(CC) $(STD) $(CFLAGS) -Ibench -Itests -I$(RB) -o $@ $(RENDER_SRC) -lvulkan -lm

# SPIR-V as a C array (glslangValidator --vn); its messages go to the log, shown on failure.
define render_spv
$(RB)/spv_$(1).h: $(2) bench/render/params.glsl
	@mkdir -p $$(@D)
	@glslangValidator -V --vn render_spv_$(1) -o $$@ $$< >$$@.log || { cat $$@.log; exit 1; }
endef
$(foreach s,$(RENDER_SHADERS),$(eval $(call render_spv,$(word 1,$(subst :, ,$(s))),bench/render/$(word 2,$(subst :, ,$(s))))))
$(eval $(call render_spv,ptp,$(RB)/ptp.comp))
$(eval $(call render_spv,ptp_cert,$(RB)/ptp_cert.comp))
$(eval $(call render_spv,ptp_table,$(RB)/ptp_table.comp))

# ptp-tcs and ptp-tcs-certified: patch.tesc classifying its own patch with the functions of
# --stage function (the certified ones under the same names, from their own folder).
$(RB)/spv_tesc_ptp.h: bench/render/patch.tesc bench/render/params.glsl $(RB)/ptp_3x3.glsl
	@mkdir -p $(@D)
	@glslangValidator -V -DPTP_TCS -I$(RB) --vn render_spv_tesc_ptp -o $@ $< >$@.log || { cat $@.log; exit 1; }

$(RB)/spv_tesc_ptp_cert.h: bench/render/patch.tesc bench/render/params.glsl $(RB)/cert/ptp_3x3.glsl
	@glslangValidator -V -DPTP_TCS -I$(RB)/cert --vn render_spv_tesc_ptp_cert -o $@ $< >$@.log || { cat $@.log; exit 1; }

$(RB)/ptp_3x3.glsl: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target glsl --stage function -o $@

$(RB)/cert/ptp_3x3.glsl: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target glsl --stage function --certified --prefix ptp_3x3_ -o $@

$(RB)/ptp_table.comp: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target glsl --space clip --kernel table -o $@

$(RB)/ptp.comp: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target glsl --space clip -o $@

$(RB)/ptp_cert.comp: $(B)/ptpgen
	@mkdir -p $(@D)
	$(B)/ptpgen --degree 3 --target glsl --space clip --certified --prefix ptp_3x3_ -o $@

# The kernels' patches per workgroup (the default schedule), for the host's dispatch.
$(RB)/ptp_groups.h: $(RB)/ptp.comp $(RB)/ptp_cert.comp $(RB)/ptp_table.comp
	@{ sed -n 's/^#define PTP_3X3_Q \([0-9]*\)u.*/#define RENDER_PTP_Q \1u/p' $(RB)/ptp.comp; \
	   sed -n 's/^#define PTP_3X3_Q \([0-9]*\)u.*/#define RENDER_PTP_CERT_Q \1u/p' $(RB)/ptp_cert.comp; \
	   sed -n 's/^#define PTP_3X3_Q \([0-9]*\)u.*/#define RENDER_PTP_TABLE_Q \1u/p' $(RB)/ptp_table.comp; } >$@.tmp
	@test "$$(wc -l <$@.tmp)" = 3 || { echo "no PTP_3X3_Q in $(RB)/ptp*.comp"; exit 1; }
	@mv $@.tmp $@

# `make figures`: build/render over tessellation factors 1 to 64 for every cull method on the
# knot and the teapot of models/, or with MODELS=DIR on DIR's bigguy.bez and teapot.bez
# (bench/render/figures.py): bench/figures/ gets the Figure-1 images, gnuplot plots
# of frame time and tessellation work against the factor, and table.md. gnuplot comes from Debian
# (installed when missing and run as root). FIGURES_ARGS=--quick for a short run, --one-view for
# every factor from the first view alone.
FIGURES_ARGS ?=

figures: build/render $(KNOT)
	@command -v gnuplot >/dev/null 2>&1 || { [ "$$(id -u)" = 0 ] && \
	    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq gnuplot-nox >/dev/null; } || \
	    { echo "figures: gnuplot is missing (apt-get install gnuplot-nox)"; exit 1; }
	python3 bench/render/figures.py build/render bench/figures $(if $(MODELS),--models $(MODELS)) \
	    $(FIGURES_ARGS)

.PHONY: render figures models

# Fuzzing verify's parsers with libFuzzer (clang): `make fuzz FUZZ_SECONDS=600`. New inputs
# collect in build/fuzz/corpus; copy an input that fails into tests/fuzz/regressions/, which the
# tests replay (with the seeds: tests/fuzz/verify/ and $(B)/fuzz_seeds/) under AddressSanitizer
# and UBSan.
FUZZ_SECONDS ?= 300
SAN = -g -O1 -fsanitize=address,undefined -fno-sanitize-recover=all

fuzz:
	@$(MAKE) -s CC=clang build/clang/templates.c build/clang/fuzz_seeds.ok
	@mkdir -p build/fuzz/corpus
	clang $(STD) $(SAN) -fsanitize=fuzzer -Igen -o build/fuzz/fuzz_verify tests/fuzz_verify.c \
	    $(filter-out gen/cli/main.c,$(GEN_SRC)) build/clang/templates.c -lm
	build/fuzz/fuzz_verify -max_total_time=$(FUZZ_SECONDS) -max_len=65536 -timeout=10 \
	    build/fuzz/corpus tests/fuzz/verify build/clang/fuzz_seeds tests/fuzz/regressions

# The seeds that are a table with one deliberate edit (ptpgen's, or a hand-written seed's), each
# checked to be judged by verify as it is meant to be (tests/fuzz/seeds.sh).
$(B)/fuzz_seeds.ok: tests/fuzz/seeds.sh $(wildcard tests/fuzz/verify/*) $(B)/ptpgen
	rm -rf $(B)/fuzz_seeds
	bash tests/fuzz/seeds.sh $(B)/ptpgen $(B)/fuzz_seeds
	@touch $@

$(B)/replay_verify: tests/fuzz_verify.c $(LIB_SRC) $(GEN_HDR) Makefile
	$(CC) $(STD) $(SAN) -DFUZZ_REPLAY -Igen -o $@ $< $(LIB_SRC) -lm

# The vendored sources: every target with a file suffix in `ptpgen --list-targets` (all but
# stats) for common degrees, quads and triangles (clip space, the default schedule). `make out` regenerates out/; the
# tests regenerate into a temporary OUTDIR with the gcc and the clang build and require identical bytes.
OUT_DEGREES = 1x1 2x2 3x3 4x4 1x3 3x1 2x3 3x2
# Triangular patches (--domain triangle) of these degrees go to out/tri<d>/ptp_tri<d><suffix>.
OUT_TRI_DEGREES = 1 2 3 4
OUTDIR ?= out
PTPGEN_BIN ?= ./ptpgen

out: ptpgen
	@files=$$($(PTPGEN_BIN) --list-targets | awk '$$2 != "-" { print $$1 ":" $$2 }') && \
	    [ -n "$$files" ] || exit 1; \
	for d in $(OUT_DEGREES); do \
	    mkdir -p $(OUTDIR)/$$d || exit 1; \
	    for te in $$files; do \
	        $(PTPGEN_BIN) --degree $$d --target $${te%%:*} -o $(OUTDIR)/$$d/ptp_$$d$${te#*:} || exit 1; \
	    done; \
	done; \
	for d in $(OUT_TRI_DEGREES); do \
	    mkdir -p $(OUTDIR)/tri$$d || exit 1; \
	    for te in $$files; do \
	        $(PTPGEN_BIN) --domain triangle --degree $$d --target $${te%%:*} \
	            -o $(OUTDIR)/tri$$d/ptp_tri$$d$${te#*:} || exit 1; \
	    done; \
	done

clean:
	rm -rf build ptpgen

FORCE:
.PHONY: all test install bench-gen build-tests out fuzz clean osd-models FORCE

# `make cullrate`: the average number of patches NCONE, TCONE and ptpgen's tangent-plane test
# (strict, strict with --coordinates absolute, degenerate, certified, --refine 1 to 3, --refine 3
# --certified) cull from 10,000 random eye points around the knot, the teapot set of models/, the
# far model, the OpenSubdiv models (below), each model of MODELS=DIR, and the PN triangles of the
# knot and the teapot
# (--pn), with a bracket of the exact answer
# (CVis). CULLRATE_ARGS passes options, e.g. `make cullrate CULLRATE_ARGS=--quick`, or `CULLRATE_ARGS="--model my.bez"` to measure your own models.
# It ends with `make cullrate-gpu` (below).
CULLRATE_ARGS ?=
CR = $(B)/cullrate

cullrate: $(CR)/cullrate $(KNOT) $(FAR) osd-models
	$(CR)/cullrate $(if $(MODELS),--models $(MODELS)) $$(test -d $(OSD) && echo --models $(OSD)) \
	    $(CULLRATE_ARGS)
	@$(MAKE) -s cullrate-gpu

# cullrate's OpenSubdiv models (bench/osd_model.cpp): the closed cage of bench/osd_cage.h, 390
# units from the origin, refined by Far at isolation levels 2 and 3 (B-spline end caps), as
# Bezier patches in build/models/osd/; one line, and none, without libosd-dev (tests/deps.sh).
OSD = build/models/osd
$(B)/osd_model: bench/osd_model.cpp bench/osd_cage.h
	@mkdir -p $(@D)
	$(CXX) -std=c++11 -O2 -Wall -Wextra -Werror -pedantic -Ibench -o $@ bench/osd_model.cpp -losdCPU
$(OSD)/osd%.bez: $(B)/osd_model
	@mkdir -p $(@D)
	$(B)/osd_model $* $@.tmp && mv $@.tmp $@
osd-models:
	@if [ -e /usr/include/opensubdiv/version.h ]; then $(MAKE) -s $(OSD)/osd2.bez $(OSD)/osd3.bez; \
	else echo "cullrate: no OpenSubdiv models (libosd-dev is missing; tests/deps.sh installs it)"; fi

# `make cullrate-gpu`: the certified GPU kernels' culls on the knot (BigGuy with MODELS=DIR
# where DIR has it) as the GPU targets compute them
# (GLSL and HLSL on lavapipe, OpenCL on PoCL, WGSL on wgpu-native, CUDA emulated on the CPU with
# g++; bench/gpu_cullrate.sh), at CULLRATE_GPU_EYES eyes per radius. A target whose host cannot be
# built is skipped.
CULLRATE_GPU_EYES ?= 2

cullrate-gpu: $(B)/ptpgen $(KNOT)
	@mkdir -p $(CR)
	@$(MAKE) -s -k $(B)/host_opencl $(B)/host_vulkan $(B)/host_wgpu $(B)/libptptest.a >$(CR)/hosts.log 2>&1 || true
	MODELS=$(MODELS) bash bench/gpu_cullrate.sh $(B) $(CULLRATE_GPU_EYES)

$(CR)/cr_s.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --degree 3 --target c --space world --rule strict --prefix cr_s_ -o $@

# The same in absolute coordinates (the formulation before local ones), for cullrate's closing table.
$(CR)/cr_sa.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --degree 3 --target c --space world --rule strict --coordinates absolute \
	    --prefix cr_sa_ -o $@

$(CR)/cr_d.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --degree 3 --target c --space world --rule degenerate --prefix cr_d_ -o $@

$(CR)/cr_c.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --degree 3 --target c --space world --certified --prefix cr_c_ -o $@

$(CR)/cr_r%.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --degree 3 --target c --space world --refine $* --prefix cr_r$*_ -o $@

$(CR)/cr_cr3.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --degree 3 --target c --space world --certified --refine 3 --prefix cr_cr3_ -o $@

$(CR)/cr_t.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --degree 3 --target table --prefix cr_t_ -o $@

# The same for cubic triangles (PN triangles): strict, degenerate, certified and the table.
$(CR)/cr_ts.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --domain triangle --degree 3 --target c --space world --rule strict \
	    --prefix cr_ts_ -o $@

$(CR)/cr_td.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --domain triangle --degree 3 --target c --space world --rule degenerate \
	    --prefix cr_td_ -o $@

$(CR)/cr_tc.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --domain triangle --degree 3 --target c --space world --certified \
	    --prefix cr_tc_ -o $@

$(CR)/cr_tt.h: $(B)/ptpgen
	@mkdir -p $(CR)
	$(B)/ptpgen --domain triangle --degree 3 --target table --prefix cr_tt_ -o $@

CR_SRC = bench/cullrate.c bench/bezfile.c bench/cones.c bench/exact.c bench/pn.c bench/tess.c
CR_HDR = bench/bezfile.h bench/cones.h bench/vec3.h \
    bench/exact.h bench/pn.h bench/tess.h tests/float_widen.h \
    $(addprefix $(CR)/,cr_s.h cr_sa.h cr_d.h cr_c.h cr_r1.h cr_r2.h cr_r3.h cr_cr3.h cr_t.h) \
    $(addprefix $(CR)/,cr_ts.h cr_td.h cr_tc.h cr_tt.h)

$(CR)/cullrate: $(CR_SRC) $(CR_HDR) Makefile
	$(BENCH_CC) $(STD) $(BENCH_CFLAGS) -pthread -Ibench -Itests -I$(CR) -o $@ $(CR_SRC) -lm

# Checks of the PN triangles, the tessellator and the triangular cones (tests/test_cullrate.sh).
$(CR)/pn_check: tests/pn_check.c $(filter-out bench/cullrate.c,$(CR_SRC)) $(CR_HDR) Makefile
	$(CC) $(STD) $(CFLAGS) -Ibench -I$(CR) -o $@ $< $(filter-out bench/cullrate.c,$(CR_SRC)) -lm

.PHONY: cullrate cullrate-gpu
