#!/usr/bin/env bash
# gpu_cullrate.sh: what the certified GPU kernels cull on a model (bench/gpu_lib.sh: the knot, or
# BigGuy with MODELS=DIR) as the GPU targets compute them
# (table kernels: GLSL and HLSL on lavapipe, OpenCL on PoCL, WGSL on wgpu-native, CUDA emulated on the CPU by
# tests/cuda_emu.h: "cuda-emu"), against the plain kernels of the same rule.
#   bash bench/gpu_cullrate.sh BUILD [NEYES]   (BUILD holds ptpgen and the hosts; default 2 eyes
#   per radius and space; MODELS=DIR: BigGuy from DIR). `make cullrate-gpu` runs it.
# Columns: the patches plain and certified call back and front (b/f); the back or front classes
# certified gives up against plain (the difference of the counts, and its share of plain's) and
# against the double reference outside its float bound (kref's "given up"); certified culls that
# are wrong: on the model, of patches within the float bound, decided by the double reference to its
# own rounding ("undecided" counts the rest; outside the bound the host's checks fail on any),
# and on kref's exact integer sets (--exact 5 200), decided exactly. "opencl": whether a cuda-emu
# row's counts equal OpenCL's, whose kernels compute the same float operations in the same order.
set -u
B=$1 neyes=${2:-2}
. bench/gpu_lib.sh

targets=""
if command -v glslangValidator >/dev/null && [ -x "$B/host_vulkan" ]; then targets="$targets glsl hlsl"
else echo "# skip glsl and hlsl: need glslangValidator and $B/host_vulkan"; fi
if [ -x "$B/host_opencl" ]; then targets="$targets opencl"; else echo "# skip opencl: no $B/host_opencl"; fi
if [ -x "$B/host_wgpu" ]; then targets="$targets wgsl"; else echo "# skip wgsl: no $B/host_wgpu"; fi
CXX=${CXX:-g++}
if command -v "$CXX" >/dev/null && [ -e "$B/libptptest.a" ]; then targets="$targets cuda-emu"
else echo "# skip cuda-emu: need $CXX and $B/libptptest.a"; fi

# kernel TARGET SPACE RULE KIND: generates the kernel (KIND plain or certified) and prints the
# host command's start for it; nothing on failure (the message goes to stderr).
kernel() {
    local f="$tmp/$1-$2-$3-$4" cert="" t=${1%-emu}
    [ "$4" = certified ] && cert=--certified
    # a short prefix: the default names of the degenerate certified kernels grow long
    "$B/ptpgen" --degree 3 --space "$2" --rule "$3" $cert --kernel table --prefix gc_ --target $t -o "$f.$t" >&2 || return
    case $1 in
    glsl) glslangValidator -S comp -V "$f.glsl" -o "$f.spv" >"$f.err" || { head -3 "$f.err" >&2; return; }
          echo "$B/host_vulkan $f.spv" ;;
    hlsl) glslangValidator -D -S comp -e main -V "$f.hlsl" -o "$f.spv" >"$f.err" || { head -3 "$f.err" >&2; return; }
          echo "$B/host_vulkan $f.spv --groups-x-constant" ;;
    opencl) echo "$B/host_opencl $f.opencl --kernel gc_classify" ;;
    wgsl) echo "$B/host_wgpu $f.wgsl" ;;
    cuda-emu) "$CXX" -x c++ -std=c++17 -O2 -march=native -ffp-contract=off -fno-fast-math -DCUDA_EMU -Igen \
              -Itests -I"$tmp" -DKERNEL_FILE="\"${f##*/}.cuda\"" -DKERNEL=gc_classify tests/host_cuda.cu -x none \
              "$B/libptptest.a" -lm -o "$f.emu" >&2 || return
          echo "$f.emu" ;;
    esac
}

# run NAME HOST... : runs a host over the given data; its report in $tmp/out, a failure on stderr.
run() {
    local name=$1
    shift
    $@ --degree 3 3 --space "$space" --rule "$rule" --block-threads "$PQ" --patches-per-block "$Q" \
        --name "$name" >"$tmp/out" 2>&1
    grep '^not ok' "$tmp/out" >&2
}
# field PATTERN: the first match of the sed pattern's group in $tmp/out.
field() { sed -n "s/$1/\\1/p" "$tmp/out" | head -1; }
# classes: the kernel's back and front counts in $tmp/out, as "BACK FRONT".
classes() {
    local f b
    f=$(field '.*: kernel front \([0-9]*\),.*') b=$(field '.*: kernel front [0-9]*, back \([0-9]*\),.*')
    echo "${b:-0} ${f:-0}"
}

echo "$model_name, $neyes eyes per radius (kref's model views), plain and certified kernels of each rule"
printf '%-8s %-6s %-11s %-2s %13s %13s %17s %14s %17s %11s %6s\n' target space rule R "plain b/f" \
    "certified b/f" "given up (plain)" "given up (dbl)" "wrong (undecided)" "exact wrong" opencl
declare -A ocl # the opencl rows' counts by space, rule and R
for t in $targets; do
    start=$SECONDS
    for space in world clip; do
        for rule in strict degenerate; do
            plain=$(kernel $t $space $rule plain) cert=$(kernel $t $space $rule certified)
            [ -n "$plain" ] && [ -n "$cert" ] || { echo "# $t $space $rule: no kernel"; continue; }
            run "exact $t" $cert --certified --exact 5 200 5
            exact=$(field '.*kernel unsafe \([0-9]*\) .*')
            for R in 2 5; do
                run "$t plain" $plain --model "$model" "$neyes" 7 --eye-radius $R
                read -r pb pf < <(classes)
                run "$t certified" $cert --certified --model "$model" "$neyes" 7 --eye-radius $R
                read -r cb cf < <(classes)
                up=$(field '.*given up \([0-9]*\) of [0-9]* back or front.*')
                wrong=$(field '.*patches: \([0-9]* wrong, [0-9]*\) undecided.*' | sed 's/ wrong, / (/')
                p=$((pb + pf)) c=$((cb + cf)) counts="$pb/$pf $cb/$cf ${up:-?} ${wrong:-?} ${exact:-?}" same=-
                [ $t = opencl ] && ocl[$space $rule $R]=$counts
                [ $t = cuda-emu ] && [ -n "${ocl[$space $rule $R]:-}" ] && same=differs &&
                    [ "${ocl[$space $rule $R]}" = "$counts" ] && same=same
                [ $same = differs ] && echo "# $t $space $rule $R: counts differ from OpenCL's" >&2
                printf '%-8s %-6s %-11s %-2s %13s %13s %8d %7.3f%% %14s %17s %11s %6s\n' $t $space $rule \
                    $R "$pb/$pf" "$cb/$cf" $((p - c)) "$(echo "$p $c" | awk '{print $1 ? 100 * ($1 - $2) / $1 : 0}')" \
                    "${up:-?}" "${wrong:-?})" "${exact:-?}" $same
            done
        done
    done
    echo "# $t: $((SECONDS - start)) s"
done
