#!/bin/sh
# tests/tui-files.sh: what the interactive program writes and edits, in a real terminal
# (tmux): x exports the recorded samples as CSV into the working directory, s saves the
# set-up as a preset (its confirmation before replacing, bad names refused), and the
# chain's elements edited one by one (Tab, Enter, c) are shown, followed by the modes
# view, saved and loaded again. Run from the repository root as `sh tests/tui-files.sh`,
# SPRINGSIM naming the binary. Ends with "tui-files: N passed, M failed".
NAME=tui-files
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

mkdir -p "$tmp/exp"
start_in "$tmp/exp" export 120 40
start save 120 40 "XDG_CONFIG_HOME=$tmp/xdg-save" -- -p 3-mass-chain
start edit 120 40 "XDG_CONFIG_HOME=$tmp/xdg-edit" -- -p 3-mass-chain
# A path too long for the status line: the reason it failed is still said (the line cut
# it off after the path). A user directory 300 bytes deep whose springsim is a file, and
# X with a name of 252 bytes (253 with .svg: too long).
longdir=$tmp/$(printf '%0200d' 0)/$(printf '%0100d' 0)
mkdir -p "$longdir"
: >"$longdir/springsim"
start_in "$tmp/exp" long 120 40 "XDG_CONFIG_HOME=$longdir"
if up export; then keys Space; fi
"$SPRINGSIM" -p 3-mass-chain --modes >"$tmp/modes.orig" 2>&1

# ---- s: save a preset ----
xs=$tmp/xdg-save
pdir=$xs/springsim/presets
save_as() { # save_as NAME: s, NAME, Enter; true once the prompt is gone
    keys s
    wait_for 'save preset as' 3 || return 1
    [ -n "$1" ] && text "$1"
    keys Enter
    wait_gone 'save preset as' 3
}
if up save; then
    if save_as mychain && wait_all 3 "has 'saved ' && has 'springsim/presets/mychain.ini'"; then pass; else
        fail "save: s, mychain, Enter should say 'saved' and the path; screen: $(brief)"
    fi
    if [ -f "$pdir/mychain.ini" ]; then
        pass
        cp "$pdir/mychain.ini" "$tmp/mychain.1"
        XDG_CONFIG_HOME=$xs "$SPRINGSIM" -p mychain --modes >"$tmp/modes.saved" 2>&1
        if [ "$(awk -F, 'NR > 1 { printf "%.3f ", $2 }' "$tmp/modes.saved")" = "0.385 0.712 0.930 " ] &&
            cmp -s "$tmp/modes.saved" "$tmp/modes.orig"; then pass; else
            fail "save: -p mychain --modes should print what -p 3-mass-chain --modes does; got: $(head -n 4 "$tmp/modes.saved" | tr '\n' '|')"
        fi
    else
        fail "save: expected the file \$XDG_CONFIG_HOME/springsim/presets/mychain.ini; found: $(find "$xs" 2>/dev/null | tr '\n' ' ')"
    fi
    # change a value, save under the same name: n keeps the file, y replaces it
    if select_control Amplitude; then
        keys Right
        if wait_re 'Amplitude +0\.10 m' 2; then
            keys s
            wait_for 'save preset as' 3
            text mychain
            keys Enter
            if wait_for 'replace it? (y/n)' 3; then
                pass
                keys n
                if wait_gone 'replace it?' 3 && cmp -s "$tmp/mychain.1" "$pdir/mychain.ini"; then pass; else
                    fail "save: n to 'replace it?' should keep the old file; screen: $(brief)"
                fi
                keys s
                wait_for 'save preset as' 3
                text mychain
                keys Enter
                wait_for 'replace it? (y/n)' 3
                keys y
                if wait_for 'saved ' 3 && ! cmp -s "$tmp/mychain.1" "$pdir/mychain.ini" &&
                    grep -qE '^amplitude *= *0\.1$' "$pdir/mychain.ini"; then pass; else
                    fail "save: y to 'replace it?' should write the new amplitude 0.1; file: $(grep amplitude "$pdir/mychain.ini"); screen: $(brief)"
                fi
            else
                fail "save: saving mychain again should ask 'replace it? (y/n)'; screen: $(brief)"
            fi
        else
            fail "save: → on Amplitude should make it 0.10 m; screen: $(brief "$scr" Amplitude)"
        fi
    else
        fail "save: cannot select the Amplitude control; screen: $(brief "$scr" Amplitude)"
    fi
    # bad names: a message, nothing written
    find "$xs" 2>/dev/null | sort >"$tmp/xs.before"
    long=$(awk 'BEGIN { while (i++ < 65) printf "a" }')
    for nm in ../x '' a/b "$long" résumé; do
        case $nm in '') what="an empty name" ;; "$long") what="a 65-character name" ;; *) what="'$nm'" ;; esac
        if save_as "$nm"; then
            l=$(last_line)
            case $l in
            *saved* | *"space start"* | '') fail "save with $what: expected a message saying why not; message line: '$l'" ;;
            *) pass ;;
            esac
        else
            fail "save with $what: the prompt did not come and go; screen: $(brief)"
            break
        fi
        find "$xs" 2>/dev/null | sort >"$tmp/xs.after"
        if cmp -s "$tmp/xs.before" "$tmp/xs.after"; then pass; else
            fail "save with $what: nothing should be written, new: $(comm -13 "$tmp/xs.before" "$tmp/xs.after" | sed "s|^$xs/||" | tr '\n' ' ')"
            cp "$tmp/xs.after" "$tmp/xs.before"
        fi
    done
fi

# ---- per-element editing ----
xe=$tmp/xdg-edit
if up edit; then
    keys Tab
    if wait_re '└─ mass 1: m 1 kg'; then
        pass
        sed -n '3,5p' "$scr" >"$tmp/edit.scene0"
        keys Enter
        text 2.5
        keys Enter
        if wait_for 'mass 1: m = 2.5 kg' 3; then
            if has_re 'Mass +mixed kg'; then pass; else
                fail "per-element: after mass 1 = 2.5 kg the Mass control should show 'mixed kg'; screen: $(brief "$scr" 'Mass ')"
            fi
            sed -n '3,5p' "$scr" >"$tmp/edit.scene1"
            if cmp -s "$tmp/edit.scene0" "$tmp/edit.scene1"; then
                fail "per-element: mass 1 at 2.5 kg should look different from the 1 kg ones; scene unchanged: $(brief "$tmp/edit.scene1")"
            else
                pass
            fi
        else
            fail "per-element: Enter, 2.5, Enter on mass 1 should say 'mass 1: m = 2.5 kg'; screen: $(brief)"
        fi
        keys Down
        # springs numbered from 1 as in --spring, with what they join (issue 22, item 9)
        if wait_re '└─ spring 2 \(1–2\): k 10 N/m' 3; then
            keys Enter
            text 22
            keys Enter
            if wait_all 3 "has 'spring 2 (1–2): k = 22 N/m' && has_re 'Spring k +mixed N/m'"; then pass; else
                fail "per-element: spring 2 Enter 22 Enter should say 'spring 2 (1–2): k = 22 N/m' and Spring k 'mixed N/m'; screen: $(brief "$scr" 'Spring k')"
            fi
        else
            fail "per-element: ↓ from mass 1 should select spring 2 (1–2); screen: $(brief "$scr" '└─ (mass|spring)')"
        fi
        keys Up
        if wait_re '└─ mass 1: m 2\.5 kg' 3; then
            keys c
            text 0.3
            keys Enter
            if wait_all 3 "has 'mass 1: c = 0.3 N·s/m' && has_re 'Damping +mixed'"; then pass; else
                fail "per-element: c, 0.3, Enter on mass 1 should set its damping ('mass 1: c = 0.3 N·s/m', Damping 'mixed'); screen: $(brief "$scr" 'Damping')"
            fi
        else
            fail "per-element: ↑ from spring 2 should select mass 1 again; screen: $(brief "$scr" '└─ (mass|spring)')"
        fi
        # the modes view follows the edits
        "$SPRINGSIM" -n 3 --mass 2.5,1,1 --spring 10,22,10,10 --damping 0.3,0.1,0.1 --modes \
            >"$tmp/modes.cli" 2>&1
        fl=$(awk -F, 'NR > 1 { printf "%.3f ", $2 }' "$tmp/modes.cli")
        keys m
        if wait_for Modes 3; then
            missing=
            for f in $fl; do has "$f Hz" || missing="$missing $f"; done
            if [ -n "$fl" ] && [ -z "$missing" ]; then pass; else
                fail "per-element: the modes view should show the edited chain's frequencies ($fl), missing$missing; screen: $(brief "$scr" 'Hz')"
            fi
            keys m
            wait_for 'Displacement (m)' 3
        else
            fail "per-element: m should open the modes view; screen: $(brief)"
        fi
        keys s
        wait_for 'save preset as' 3
        text pe
        keys Enter
        f=$xe/springsim/presets/pe.ini
        if wait_for 'saved ' 3 && [ -f "$f" ]; then
            if grep -qE '^mass *= *2\.5, *1, *1$' "$f" &&
                grep -qE '^damping *= *0\.3, *0\.1, *0\.1$' "$f" &&
                awk -F'[=,]' '/^spring *=/ { n = NF - 1; k2 = $3 + 0 } END { exit !(n == 4 && k2 == 22) }' "$f"; then
                pass
            else
                fail "per-element: pe.ini should have mass = 2.5, 1, 1, damping 0.3, 0.1, 0.1 and four springs with 22 second; it has: $(grep -E '^(mass|spring|damping) *=' "$f" | tr '\n' '|')"
            fi
            XDG_CONFIG_HOME=$xe "$SPRINGSIM" -p pe --modes >"$tmp/modes.pe" 2>&1
            if cmp -s "$tmp/modes.pe" "$tmp/modes.cli" && ! cmp -s "$tmp/modes.pe" "$tmp/modes.orig"; then pass; else
                fail "per-element: -p pe --modes should match --mass 2.5,1,1 --spring 10,22,10,10 --damping 0.3,0.1,0.1 --modes and differ from the uniform chain; got: $(head -n 2 "$tmp/modes.pe" | tr '\n' '|')"
            fi
        else
            fail "per-element: s, pe, Enter should save \$XDG_CONFIG_HOME/springsim/presets/pe.ini; screen: $(brief)"
        fi
    else
        fail "per-element: Tab should select mass 1 ('mass 1: m 1 kg' on the scene's border); screen: $(brief "$scr" 'mass 1')"
    fi
fi

# ---- x: export CSV into the working directory ----
S=export
if wait_t 1; then
    keys Space
    t=$(settled_t)
    keys x
    if wait_re 'exported [0-9]+ rows \(t = 0 to [0-9.]+ s\) to \./springsim-[0-9]{8}-[0-9]{6}\.csv'; then
        pass
        n=$(sed -n 's/.*exported \([0-9][0-9]*\) rows .* to .*/\1/p' "$scr" | head -n 1)
        f=$(sed -n 's/.*exported [0-9]* rows .* to \.\/\(springsim-[0-9]*-[0-9]*\.csv\).*/\1/p' "$scr" | head -n 1)
        if [ -f "$tmp/exp/$f" ] && [ "$(ls -A "$tmp/exp" | wc -l)" -eq 1 ]; then
            pass
            # --meta's lines first: the version, the command line, what the file holds
            if awk -F, -v n="$n" -v t="$t" '
                NR == 1 { ok = ($0 ~ /^# springsim [0-9]+\.[0-9]+\.[0-9]+$/); next }
                NR == 2 { ok = ok && ($0 ~ /^# springsim --headless --sample 0\.01 --masses 2 .* --duration /); next }
                NR == 3 { ok = ok && index($0, "# exported from the interactive program at t = ") == 1 &&
                          index($0, ": " n " rows from t = 0.00 s, every 0.01 s;") > 0; next }
                NR == 4 { ok = ok && ($0 == "t,x1,x2,v1,v2,a1,a2,motor"); next }
                { rows++
                  if (NF != 8 || tolower($0) ~ /nan|inf/) ok = 0
                  for (i = 1; i <= NF; i++) if ($i !~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) ok = 0
                  if (rows > 1 && $1 + 0 <= last) ok = 0
                  last = $1 + 0 }
                END { exit !(ok && rows == n && rows > 50 && last > t - 0.005 && last < t + 0.005) }' \
                "$tmp/exp/$f"; then pass; else
                fail "export: $f should have 3 '#' lines (version, --headless command, what it holds), the header t,x1,x2,v1,v2,a1,a2,motor, $n rows of 8 numbers, t increasing to $t; it has $(($(wc -l <"$tmp/exp/$f") - 4)) rows: $(sed -n '1,5p;$p' "$tmp/exp/$f" | cut -c 1-120 | tr '\n' '|')"
            fi
        else
            fail "export: expected only $f in the working directory; found: $(ls -A "$tmp/exp" | tr '\n' ' ')"
        fi
    else
        fail "export: x should say 'exported N rows (t = 0 to T s) to ./springsim-YYYYmmdd-HHMMSS.csv'; screen: $(brief)"
    fi
else
    fail "export: expected it to run to t = 1 s; screen: $(brief)"
fi

# ---- a long path in a message keeps the reason ----
if up long; then
    keys s
    wait_for 'save preset as' 3
    text longpath
    keys Enter
    if wait_for 'Not a directory' 3; then pass; else
        fail "save under a 300-byte XDG_CONFIG_HOME whose springsim is a file: expected the reason 'Not a directory' said; screen: $(brief "$scr" 'save')"
    fi
    keys X
    wait_for 'figure name' 3
    text "$(printf '%0252d' 0)"
    keys Enter
    if wait_for 'File name too long' 5; then pass; else
        fail "X with a name of 252 bytes: expected the reason 'File name too long' said; screen: $(brief "$scr" 'figure')"
    fi
fi

all_alive export save edit long

summary
