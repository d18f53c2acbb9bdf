#!/bin/sh
# mk/deps.sh GROUP...: makes sure the Debian packages a build step needs are present.
# Groups: build (compiler, pkg-config, ncursesw, libinih, LAPACKE, GSL, FFTW3, cairo,
# fontconfig, libsixel, GLib for base64, libunistring for Unicode's classes), test (cmocka,
# tmux, bash, zsh and fish for the completions, numpy and pandas for --meta's CSV, GNU
# parallel for the --summary study, libsixel's tools, Xvfb, xterm, ImageMagick, the DejaVu
# fonts and pyte for the pixel tests and screenshots, ncurses-term for xterm-direct), deb
# (dpkg-dev, debhelper, lintian, build-essential), bench (GSL), valgrind, fuzz (clang with
# libFuzzer). As root the missing ones are installed with apt-get; otherwise the one
# apt-get line to run is printed and the step stops.
need=""
has_pc() { pkg-config --exists "$1" 2>/dev/null; }
want_pc() { has_pc "$1" || need="$need $2"; }
want_bin() { command -v "$1" >/dev/null 2>&1 || need="$need $2"; }
want_py() { /usr/bin/python3 -c "import $1" 2>/dev/null || need="$need $2"; }

for group in "$@"; do
    case $group in
    build)
        want_bin cc gcc
        want_bin pkg-config pkgconf
        want_pc ncursesw libncurses-dev
        want_pc inih libinih-dev
        want_pc lapacke liblapacke-dev
        want_pc gsl libgsl-dev
        want_pc fftw3 libfftw3-dev
        want_pc cairo libcairo2-dev
        want_pc fontconfig libfontconfig-dev
        want_pc libsixel libsixel-dev
        want_pc glib-2.0 libglib2.0-dev
        [ -e /usr/include/unictype.h ] || need="$need libunistring-dev"
        ;;
    test)
        want_pc cmocka libcmocka-dev
        want_bin tmux tmux
        want_bin bash bash
        want_bin zsh zsh
        want_bin fish fish
        want_py numpy python3-numpy
        want_py pandas python3-pandas
        want_bin parallel parallel
        want_bin img2sixel libsixel-bin
        want_bin Xvfb xvfb
        want_bin xterm xterm
        want_bin convert imagemagick
        want_bin identify imagemagick
        want_bin import imagemagick
        want_bin pdftotext poppler-utils
        want_bin pdfinfo poppler-utils
        want_py pyte python3-pyte
        [ -e /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf ] || need="$need fonts-dejavu-core"
        infocmp xterm-direct >/dev/null 2>&1 || need="$need ncurses-term"
        ;;
    bench)
        want_pc gsl libgsl-dev
        ;;
    deb)
        want_bin dpkg-buildpackage dpkg-dev
        want_bin dh debhelper
        want_bin lintian lintian
        [ -e /usr/share/build-essential/essential-packages-list ] || need="$need build-essential"
        ;;
    valgrind)
        want_bin valgrind valgrind
        ;;
    fuzz)
        want_bin clang clang
        [ -n "$(find /usr/lib/llvm-*/lib/clang -name 'libclang_rt.fuzzer*.a' 2>/dev/null | head -n 1)" ] ||
            need="$need libclang-rt-14-dev"
        ;;
    *)
        echo "mk/deps.sh: unknown group '$group'" >&2
        exit 2
        ;;
    esac
done

[ -z "$need" ] && exit 0
need=$(printf '%s\n' $need | sort -u | tr '\n' ' ' | sed 's/ $//')
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "springsim: installing Debian packages: $need"
    apt-get update -qq >/dev/null &&
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $need >/dev/null ||
        { echo "springsim: apt-get could not install: $need" >&2; exit 1; }
else
    echo "springsim: missing Debian packages; install them with:" >&2
    echo "    apt-get install $need" >&2
    exit 1
fi
