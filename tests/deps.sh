# deps.sh: makes sure the commands the tests run are installed (sourced by tests/run.sh).
# Missing ones are installed from Debian's packages; under CI=true one still missing is a failure.

# command -> Debian package
PTP_DEPS="gcc:gcc clang:clang make:make python3:python3"

# Prints the commands of PTP_DEPS that are not on PATH.
ptp_missing_deps() {
    local d
    for d in $PTP_DEPS; do
        command -v "${d%%:*}" >/dev/null 2>&1 || echo "${d%%:*}"
    done
}

# Installs the packages of missing commands when running as root; reports what stays missing
# as a "not ok" line (CI) or a "# skip" note (a developer's machine without root).
ptp_ensure_deps() {
    local missing pkgs d c
    missing=$(ptp_missing_deps)
    [ -z "$missing" ] && return 0
    pkgs=""
    for c in $missing; do
        for d in $PTP_DEPS; do
            [ "${d%%:*}" = "$c" ] && pkgs="$pkgs ${d#*:}"
        done
    done
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        echo "# installing:$pkgs"
        { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $pkgs; } >&2 ||
            echo "# apt-get failed for:$pkgs"
    fi
    for c in $(ptp_missing_deps); do
        if [ "${CI:-}" = true ]; then
            echo "not ok - dependency '$c' is missing and could not be installed"
        else
            echo "# skip: '$c' is missing (install it, or run as root to let make test do it)"
        fi
    done
}
