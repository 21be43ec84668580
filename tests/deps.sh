# deps.sh: makes sure what the tests run is installed (sourced by tests/run.sh).
# Missing packages are installed from Debian's; under CI=true one still missing is a failure.

# what -> Debian package; "what" is a command, an absolute path for a file a package ships, or
# py.MODULE for a module python3 must import (ensurepip: what `python3 -m venv` needs).
PTP_DEPS="gcc:gcc g++:g++ clang:clang make:make cmake:cmake python3:python3 py.ensurepip:python3-venv
glslangValidator:glslang-tools spirv-val:spirv-tools
/usr/include/CL/cl.h:opencl-headers /usr/lib/x86_64-linux-gnu/libOpenCL.so:ocl-icd-opencl-dev
/etc/OpenCL/vendors/pocl.icd:pocl-opencl-icd
/usr/include/vulkan/vulkan.h:libvulkan-dev /usr/share/vulkan/icd.d/lvp_icd.x86_64.json:mesa-vulkan-drivers
x86_64-w64-mingw32-g++-posix:g++-mingw-w64-x86-64-posix /usr/include/opensubdiv/version.h:libosd-dev"

# Prints each entry "what:package" of PTP_DEPS that is missing.
ptp_missing_deps() {
    local d w
    for d in $PTP_DEPS; do
        w=${d%%:*}
        case $w in
        /*) [ -e "$w" ] || echo "$d" ;;
        py.*) python3 -c "import ${w#py.}" >/dev/null 2>&1 || echo "$d" ;;
        *) command -v "$w" >/dev/null 2>&1 || echo "$d" ;;
        esac
    done
}

# Installs the packages of missing entries when running as root; reports what stays missing
# as a "not ok" line (CI) or a "# skip" note (a developer's machine without root).
ptp_ensure_deps() {
    local missing pkgs d
    missing=$(ptp_missing_deps)
    [ -z "$missing" ] && return 0
    pkgs=$(for d in $missing; do echo "${d#*:}"; done | sort -u | tr '\n' ' ')
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        echo "# installing: $pkgs"
        { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $pkgs; } >&2 ||
            echo "# apt-get failed for: $pkgs"
    fi
    for d in $(ptp_missing_deps); do
        if [ "${CI:-}" = true ]; then
            echo "not ok - dependency '${d%%:*}' (Debian package ${d#*:}) is missing and could not be installed"
        else
            echo "# skip: '${d%%:*}' is missing (Debian package ${d#*:}; run make test as root to install it)"
        fi
    done
}

# wgpu-native, WebGPU's C API (webgpu.h, wgpu.h, libwgpu_native-release.so), for the WGSL host:
# it ships in the wheel of the PyPI package wgpu, installed with pip into a virtual environment
# under build/. Pinned: the C API changes between releases (wgpu 0.32.0 is wgpu-native 29.0.1.1).
PTP_WGPU_VERSION=0.32.0
PTP_VENV=build/venv

# Prints the folder with the headers and the library when the pinned wheel is installed there.
ptp_wgpu_dir() {
    local d
    for d in "$PWD/$PTP_VENV"/lib/python3*/site-packages; do
        [ -d "$d/wgpu-$PTP_WGPU_VERSION.dist-info" ] || continue
        d=$d/wgpu/resources
        [ -f "$d/webgpu.h" ] && [ -f "$d/wgpu.h" ] && [ -f "$d/libwgpu_native-release.so" ] &&
            echo "$d" && return 0
    done
    return 1
}

# Makes sure the pinned wheel is in $PTP_VENV (creating it and running pip when it is not) and
# exports WGPU_DIR for the Makefile. A runtime still missing is a "not ok" line under CI=true,
# else a "# skip" note.
ptp_ensure_wgpu() {
    if ! WGPU_DIR=$(ptp_wgpu_dir); then
        echo "# installing wgpu==$PTP_WGPU_VERSION (wgpu-native) into $PTP_VENV"
        { [ -x "$PTP_VENV/bin/pip" ] || python3 -m venv "$PTP_VENV"; } >&2 &&
            "$PTP_VENV/bin/pip" install -q "wgpu==$PTP_WGPU_VERSION" >&2 ||
            echo "# pip install wgpu==$PTP_WGPU_VERSION failed"
        WGPU_DIR=$(ptp_wgpu_dir)
    fi
    if [ -n "$WGPU_DIR" ]; then
        export WGPU_DIR
    elif [ "${CI:-}" = true ]; then
        echo "not ok - dependency wgpu-native (pip wgpu==$PTP_WGPU_VERSION in $PTP_VENV) is missing and could not be installed"
    else
        echo "# skip: wgpu-native is missing (pip wgpu==$PTP_WGPU_VERSION in $PTP_VENV could not be installed): no WGSL tests"
    fi
}
