# host_lib.sh: the check-line helpers of the test scripts (sourced by tests/kernels_lib.sh,
# test_wgpu.sh, test_refine.sh, test_cullrate.sh and test_examples.sh).

ok() { echo "ok - $1"; }
# make_tmp: sets tmp to a new temporary directory, removed when the script exits.
make_tmp() {
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
}
notok() { echo "not ok - $1: $2"; }
# missing TOOL WHAT: under CI a missing tool is a failure; elsewhere a skip note.
missing() {
    if [ "${CI:-}" = true ]; then notok "$2" "$1 is not available"; else echo "# skip: $2 ($1 is not available)"; fi
}
# run_host NAME CMD...: runs a host, passes its check lines through, and turns a silent failure
# into a "not ok" line.
run_host() {
    local name=$1 out rc
    shift
    out=$("$@" 2>&1)
    rc=$?
    printf '%s\n' "$out" | grep -E '^(ok|not ok|#) ' || true
    if [ $rc -ne 0 ] && ! printf '%s\n' "$out" | grep -q '^not ok - '; then
        notok "$name" "exit $rc: $(printf '%s\n' "$out" | tail -3 | tr '\n' ' ')"
    fi
}
