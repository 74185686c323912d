# shellcheck shell=bash
# Shared by tools/run and tools/test: install the missing Debian packages, configure, build.
# Sourced, not executed.

STEPDECK_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# Everything a fresh Debian 12 needs to build, test and run StepDeck (see
# docs: engineering notes; libqt6opengl6-dev is only a Recommends of qt6-base-dev but
# find_package(Qt6 Charts) fails without it).
STEPDECK_PACKAGES=(
    g++ cmake ninja-build
    qt6-base-dev qt6-serialport-dev qt6-charts-dev qt6-tools-dev libqt6opengl6-dev
    qt6-translations-l10n libsdl2-dev
    socat xvfb xauth
)

stepdeck_log() { printf '==> %s\n' "$*" >&2; }
stepdeck_die() { printf 'error: %s\n' "$*" >&2; exit 1; }

# What tools/test adds: the validators of the desktop entry and the AppStream metainfo
# (tests/resources/tst_desktopintegration skips without them).
STEPDECK_TEST_PACKAGES=(desktop-file-utils appstream)

# What tools/package adds: help2man writes the man pages from --help/--version at build time,
# dpkg-dev (dpkg-shlibdeps) and file are what CPack's DEB generator needs for the Depends line.
STEPDECK_PACKAGE_PACKAGES=(help2man dpkg-dev file desktop-file-utils appstream)

# stepdeck_missing_packages [extra packages...]
stepdeck_missing_packages() {
    local p
    for p in "${STEPDECK_PACKAGES[@]}" "$@"; do
        if ! dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q 'install ok installed'; then
            printf '%s\n' "$p"
        fi
    done
}

# stepdeck_install_packages [extra packages...]
# Installs only what is missing; apt-get update runs once, and only if something is missing.
stepdeck_install_packages() {
    command -v dpkg-query >/dev/null 2>&1 ||
        stepdeck_die "dpkg-query not found: tools/ expect Debian 12 (bookworm) or a derivative"
    local missing
    mapfile -t missing < <(stepdeck_missing_packages "$@")
    if [ "${#missing[@]}" -eq 0 ]; then
        return 0
    fi
    local -a sudo=()
    if [ "$(id -u)" -ne 0 ]; then
        command -v sudo >/dev/null 2>&1 ||
            stepdeck_die "missing packages (${missing[*]}) and not root; install them or get sudo"
        # Without a terminal (CI) sudo must not wait for a password prompt nobody answers.
        if [ -t 0 ]; then sudo=(sudo); else sudo=(sudo -n); fi
    fi
    stepdeck_log "installing missing Debian packages: ${missing[*]}"
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q ||
        stepdeck_die "apt-get update failed"
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q \
        --no-install-recommends "${missing[@]}" ||
        stepdeck_die "apt-get install failed for: ${missing[*]}"
}

# stepdeck_build BUILD_DIR [extra cmake -D options...]
# STEPDECK_BUILD_TYPE overrides the configuration (default RelWithDebInfo).
stepdeck_build() {
    local dir=$1
    shift
    local -a generator=()
    # An existing build directory keeps its generator; a new one gets Ninja.
    if [ ! -f "$dir/CMakeCache.txt" ]; then
        generator=(-G Ninja)
    fi
    stepdeck_log "configuring $dir"
    mkdir -p "$dir"
    cmake -S "$STEPDECK_ROOT" -B "$dir" "${generator[@]}" \
        -DCMAKE_BUILD_TYPE="${STEPDECK_BUILD_TYPE:-RelWithDebInfo}" "$@" >"$dir/configure.log" 2>&1 || {
        cat "$dir/configure.log" >&2
        stepdeck_die "cmake configure failed ($dir)"
    }
    stepdeck_warn_low_disk "$dir"
    stepdeck_log "building $dir"
    cmake --build "$dir" --parallel "$(nproc 2>/dev/null || echo 2)" || {
        stepdeck_warn_low_disk "$dir"
        stepdeck_die "build failed ($dir)"
    }
}

# stepdeck_warn_low_disk DIR
# A compiler that runs out of disk can fail without a word of its own (seen in CI: a FAILED
# object and no diagnostic). A full build takes about 3.5 GB, 1.5 GB of it the precompiled
# headers (with the libraries shared; static, build-asan/ once took 12 GB).
stepdeck_warn_low_disk() {
    local avail_kb
    avail_kb=$(df -Pk "$1" 2>/dev/null | awk 'NR == 2 { print $4 }')
    if [ -n "$avail_kb" ] && [ "$avail_kb" -lt $((4 * 1024 * 1024)) ]; then
        printf 'warning: only %s MB free on the disk of %s; a build needs a few GB\n' \
            "$((avail_kb / 1024))" "$1" >&2
    fi
}
