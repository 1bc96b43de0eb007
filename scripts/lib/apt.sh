# The apt-get part the scripts/ensure-* installers share (sourced, not run). A script sets
#   name      its name, for its one line of output and its log (ensure-octave)
#   present   a command that succeeds when the thing is installed
#   where     optional: a command whose path the success line shows (bwrap)
# then calls  apt_ensure LABEL CONSEQUENCE PACKAGE...
# which installs the packages with apt-get when this user may (root, or passwordless sudo), updating the package
# lists once when the first attempt fails (a fresh machine has none), and prints one line saying what it did.
# LABEL names what is missing in that line; CONSEQUENCE says what happens without it ("the Octave tests will be
# skipped (or fail with CI set)"). It never fails: the tests that need the thing skip, or fail with CI set.
log="${TMPDIR:-/tmp}/fclcert-$name.log"
say() { echo "$name: $*"; }

apt_ensure() {
    label=$1
    consequence=$2
    shift 2
    if ! command -v apt-get >/dev/null 2>&1; then
        say "$label is not installed and there is no apt-get here; $consequence"
        return 0
    fi
    if [ "$(id -u)" = 0 ]; then
        as=""
    elif command -v sudo >/dev/null 2>&1 && sudo -n true >/dev/null 2>&1; then
        as="sudo -n"
    else
        say "$label is not installed and installing needs root (no passwordless sudo); $consequence"
        return 0
    fi
    if { apt_install "$@" || { $as apt-get update -q && apt_install "$@"; }; } >"$log" 2>&1 && $present >/dev/null 2>&1; then
        say "installed $1 with ${as:+$as }apt-get${where:+ ($(command -v "$where"))}"
    else
        say "could not install $1 with ${as:+$as }apt-get (see $log); $consequence"
    fi
    return 0
}

apt_install() {
    DEBIAN_FRONTEND=noninteractive $as apt-get install -y -q --no-install-recommends "$@"
}
