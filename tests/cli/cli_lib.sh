# Shared by the tests/cli scripts (sourced): failing with a message, and running hush
# expecting an exit code and a message.

fail() { echo "FAIL: $*" >&2; exit 1; }

# expect_exit <code> <message part> <hush arguments...>: runs "$hush" (set by the
# caller) and checks its exit code and that stderr contains the message part.
expect_exit() {
    local want="$1" part="$2"; shift 2
    set +e
    "$hush" "$@" > stdout.txt 2> stderr.txt
    local code=$?
    set -e
    [[ $code == "$want" ]] || fail "hush $*: exit $code, expected $want: $(cat stderr.txt)"
    grep -qF -- "$part" stderr.txt || fail "hush $*: message '$(cat stderr.txt)' lacks '$part'"
    echo "ok: hush $* -> $code: $(head -c 400 stderr.txt)"
}

# nothing_written <folder>: the folder is missing or empty.
nothing_written() { if [[ -d "$1" ]] && [[ -n "$(ls -A "$1")" ]]; then fail "wrote $(ls -A "$1")"; fi; }
