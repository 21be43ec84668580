# deps.sh: makes sure what the tests run is installed (sourced by tests/run.sh).
# Missing packages are installed from Debian's; under CI=true one still missing is a failure.

# what -> Debian package; "what" is a command, or an absolute path for a file a package ships.
PTP_DEPS="gcc:gcc clang:clang make:make python3:python3
glslangValidator:glslang-tools spirv-val:spirv-tools
/usr/include/CL/cl.h:opencl-headers /usr/lib/x86_64-linux-gnu/libOpenCL.so:ocl-icd-opencl-dev
/etc/OpenCL/vendors/pocl.icd:pocl-opencl-icd
/usr/include/vulkan/vulkan.h:libvulkan-dev /usr/share/vulkan/icd.d/lvp_icd.x86_64.json:mesa-vulkan-drivers"

# Prints each entry "what:package" of PTP_DEPS that is missing.
ptp_missing_deps() {
    local d w
    for d in $PTP_DEPS; do
        w=${d%%:*}
        case $w in
        /*) [ -e "$w" ] || echo "$d" ;;
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
