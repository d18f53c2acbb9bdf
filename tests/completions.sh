#!/bin/sh
# tests/completions.sh: the shell completions in build/completions ($COMPLETIONS), made
# from the option table. bash: the file is sourced and _springsim driven with COMP_WORDS
# and COMP_CWORD, its answers checked against the documented names, --help's options and the
# preset files; fish: its own `complete -C`; zsh: loaded in a plain zsh, then a real zsh in
# tmux completes with Tab. Prints "completions: N passed, M failed".
NAME=completions
. tests/lib/check.sh
COMPLETIONS=${COMPLETIONS:-build/completions}
case $COMPLETIONS in /*) ;; *) COMPLETIONS=$PWD/$COMPLETIONS ;; esac
presets=$PWD/presets

# Only the presets shipped in presets/ (found beside the binary), none of the user's.
plain_env
mkdir -p "$tmp/work/sub"

# Files the file-taking options see (the cases run in $tmp/work).
touch "$tmp/work/mine.ini" "$tmp/work/notes.txt" "$tmp/work/run.csv"

# words WORD... sorted, one line, for comparing answers.
words() { printf '%s\n' "$@" | sed '/^$/d' | LC_ALL=C sort | tr '\n' ' ' | sed 's/ $//'; }

# bash_complete WORD...: what _springsim offers for the command line "springsim WORD...",
# the last word being completed (an empty last word: after a space), in $got, sorted.
bash_complete() {
    got=$(cd "$tmp/work" && bash --norc --noprofile -c '
        . "$1/springsim.bash" || exit 9
        shift
        COMP_WORDS=("$@")
        COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
        _springsim
        printf "%s\n" "${COMPREPLY[@]}"' bash "$COMPLETIONS" "$SPRINGSIM" "$@" 2>"$tmp/bash.err" |
        LC_ALL=C sort | tr '\n' ' ' | sed 's/ $//')
}

# expect_bash WANT WORD...: the completion of "springsim WORD..." is exactly WANT (sorted).
expect_bash() {
    want=$1
    shift
    bash_complete "$@"
    if [ "$got" = "$want" ] && ! [ -s "$tmp/bash.err" ]; then
        pass
    else
        fail "bash: springsim $*<TAB>: expected '$want', got '$got' $(head -c 200 "$tmp/bash.err")"
    fi
}

if ! command -v bash >/dev/null 2>&1; then
    fail "bash is not installed: no completion was tested"
    summary
    exit
fi
for f in springsim.bash _springsim springsim.fish; do
    [ -s "$COMPLETIONS/$f" ] && pass || fail "$COMPLETIONS/$f was not written (make completions)"
done

# The waveforms, integrators and right ends as the man page names them.
expect_bash "sawtooth sine square" --wave s
expect_bash "euler exact rk4 semi-implicit verlet" --integrator ""
expect_bash "free motor wall" --boundary ""
expect_bash "sawtooth sine square" --wave = s       # --wave=s, split at '=' by bash
expect_bash "--wave" --wa

# Preset names come from the preset files, here those beginning with r, and .ini files
# (not other files) and directories for a preset of one's own.
rnames=$(words $(cd "$presets" && ls r*.ini | sed 's/\.ini$//'))
case " $rnames " in *" resonance "*) pass ;; *) fail "no presets/resonance.ini to complete to" ;; esac
expect_bash "$rnames" -p r
expect_bash "$rnames" --preset r
expect_bash "mine.ini" -p m
bash_complete -p ""
case " $got " in
*" mine.ini "*" sub "*) case " $got " in *notes.txt*) fail "bash: -p offers notes.txt" ;; *) pass ;; esac ;;
*) fail "bash: -p <TAB> lacks mine.ini or sub: '$got'" ;;
esac
# ... asked of the program when completing: a preset of the user's appears.
printf '[system]\nmasses = 1\n' >"$tmp/xdg/rz-mine.ini"
mkdir -p "$tmp/xdg/springsim/presets"
mv "$tmp/xdg/rz-mine.ini" "$tmp/xdg/springsim/presets/"
expect_bash "$(words $rnames rz-mine)" -p r
rm "$tmp/xdg/springsim/presets/rz-mine.ini"

# Any file for -o; nothing offered for a value the user types.
expect_bash "mine.ini notes.txt run.csv sub" -o ""
expect_bash "run.csv" --output r
expect_bash "" --masses ""
expect_bash "" --frequency 0.7
# springsim takes no arguments: after "--" nothing is offered, not even an option.
expect_bash "" -- --w
expect_bash "" --wave sine -- ""

# Every option --help lists, short and long, and no other.
options=$(words $("$SPRINGSIM" --help | sed -n '/^Options:/,/^$/p' |
    grep -oE '^  (-[a-z], )?\s*--[a-z0-9-]+' | tr -d ',' ))
expect_bash "$options" -
[ "$(echo "$options" | wc -w)" -ge 30 ] && pass || fail "--help lists too few options: $options"

# fish: its parser, then its own completion engine.
if ! command -v fish >/dev/null 2>&1; then
    fail "fish is not installed (mk/deps.sh test installs it)"
else
    fish -n "$COMPLETIONS/springsim.fish" 2>"$tmp/fish.err" && ! [ -s "$tmp/fish.err" ] &&
        pass || fail "fish -n: $(head -c 300 "$tmp/fish.err")"
    # fish_complete CMDLINE: the words fish offers, sorted.
    fish_complete() {
        got=$(cd "$tmp/work" && fish --no-config -c "source '$COMPLETIONS/springsim.fish'
            complete -C'$1'" 2>"$tmp/fish.err" | cut -f1 | LC_ALL=C sort | tr '\n' ' ' |
            sed 's/ $//')
    }
    for c in "--wave s|sawtooth sine square" "--integrator |euler exact rk4 semi-implicit verlet" \
        "-p r|$rnames" "-p m|mine.ini"; do
        fish_complete "$SPRINGSIM ${c%%|*}"
        [ "$got" = "${c#*|}" ] && ! [ -s "$tmp/fish.err" ] && pass ||
            fail "fish: springsim ${c%%|*}<TAB>: expected '${c#*|}', got '$got' $(head -c 200 "$tmp/fish.err")"
    done
    # A preset file in a directory with a blank, its name typed escaped or in quotes.
    mkdir -p "$tmp/work/my presets" && touch "$tmp/work/my presets/mass 2.ini"
    for typed in 'my\ presets/m' '"my presets/m' "'my presets/m"; do
        got=$(cd "$tmp/work" && fish --no-config -c 'source $argv[1]; complete -C "$argv[2] -p $argv[3]"' \
            "$COMPLETIONS/springsim.fish" "$SPRINGSIM" "$typed" 2>"$tmp/fish.err" | cut -f1)
        [ "$got" = "my presets/mass 2.ini" ] && ! [ -s "$tmp/fish.err" ] && pass ||
            fail "fish: springsim -p $typed<TAB>: expected 'my presets/mass 2.ini', got '$got' $(head -c 200 "$tmp/fish.err")"
    done
    rm -r "$tmp/work/my presets"
fi

# zsh: its parser, loading it where compinit runs, then Tab in a real zsh in tmux.
if ! command -v zsh >/dev/null 2>&1; then
    fail "zsh is not installed (mk/deps.sh test installs it)"
else
    zsh -n "$COMPLETIONS/_springsim" 2>"$tmp/zsh.err" && ! [ -s "$tmp/zsh.err" ] && pass ||
        fail "zsh -n: $(head -c 300 "$tmp/zsh.err")"
    HOME=$tmp zsh -f -c "autoload -U compinit && compinit -u -D && source '$COMPLETIONS/_springsim' &&
        [[ \$_comps[springsim] == _springsim ]]" >"$tmp/zsh.out" 2>&1 && ! [ -s "$tmp/zsh.out" ] &&
        pass || fail "zsh: loading _springsim: $(head -c 300 "$tmp/zsh.out")"
    if command -v tmux >/dev/null 2>&1; then
        mkdir -p "$tmp/bin"
        ln -s "$SPRINGSIM" "$tmp/bin/springsim"
        tz() { tmux -L "springsim-zsh-$$" -f /dev/null "$@"; }
        trap 'tz kill-server >/dev/null 2>&1; rm -rf "$tmp"' EXIT
        tz new-session -d -x 150 -y 30 -c "$tmp/work" \
            "env -i HOME=$tmp TERM=xterm LC_ALL=C PATH=$tmp/bin:/usr/bin:/bin XDG_CONFIG_HOME=$tmp/xdg zsh -f"
        tz send-keys "fpath=('$COMPLETIONS' \$fpath); autoload -U compinit; compinit -u -D; PS1='> '; clear" Enter
        # zsh_tab CMDLINE WANT...: Tab after CMDLINE shows every WANT word within 5 s.
        zsh_tab() {
            line=$1
            shift
            tz send-keys C-u C-l
            tz send-keys -l "$line"
            tz send-keys Tab
            i=0
            while [ $i -lt 50 ]; do
                scr=$(tz capture-pane -p)
                ok=1
                for w in "$@"; do
                    echo "$scr" | grep -qE "(^| )$w( |$)" || ok=0
                done
                [ $ok = 1 ] && break
                sleep 0.1
                i=$((i + 1))
            done
            [ $ok = 1 ] && pass || fail "zsh: $line<TAB>: expected $*, screen: $(echo "$scr" | head -n 4 | tr '\n' '|')"
        }
        zsh_tab "springsim --wave s" sawtooth sine square
        zsh_tab "springsim --integrator " euler semi-implicit verlet rk4 exact
        zsh_tab "springsim -p " $(cd "$presets" && ls *.ini | sed 's/\.ini$//') mine.ini
        tz kill-server >/dev/null 2>&1
    fi
fi

summary
