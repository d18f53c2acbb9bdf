# springsim: a terminal simulator of a driven spring-mass-damper chain.
# make            build ./springsim
# make run        build and start it on the default configuration
# make check      build and run every test, J at a time (default: the processors, at least 2)
#                 T="tui-ghost plain test_app": only those (scripts without .sh, unit tests)
# make sanitize   the tests under AddressSanitizer + UndefinedBehaviorSanitizer
# make install    PREFIX=/usr/local DESTDIR=: binary, man page, presets, lessons, shell completions
# make deb        an unsigned Debian package in build/ (debhelper, checked by lintian)
# Missing Debian packages are installed by mk/deps.sh (as root) or named (otherwise).

VERSION = 0.1.0
PREFIX ?= /usr/local
BINDIR ?= $(PREFIX)/bin
DATADIR ?= $(PREFIX)/share/springsim
MANDIR ?= $(PREFIX)/share/man/man1
BASHCOMPDIR ?= $(PREFIX)/share/bash-completion/completions
ZSHCOMPDIR ?= $(PREFIX)/share/zsh/site-functions
FISHCOMPDIR ?= $(PREFIX)/share/fish/vendor_completions.d
LIBDIR ?= $(PREFIX)/lib
FIGLIBDIR ?= $(LIBDIR)/springsim
PKG_CONFIG ?= pkg-config
CC ?= cc
BUILD ?= build
BIN ?= springsim

CFLAGS ?= -O2 -g
# No fused multiply-add with any compiler (gcc's -std=c11 already has none; clang fuses
# by default where the machine has it): every result the same bits everywhere.
WARN = -std=c11 -ffp-contract=off -Wall -Wextra -Wshadow -Wstrict-prototypes \
       -Wmissing-prototypes -Wformat=2 -Wwrite-strings -Wpointer-arith
# Make's text as one word of the shell (in single quotes, each ' as '\''), and as the
# inside of a C string (\ and " escaped): a PREFIX or DATADIR with quotes or backslashes
# is compiled in as it is.
shell_word = '$(subst ','\'',$(1))'
c_text = $(subst ",\",$(subst \,\\,$(1)))
DEFS = -D_GNU_SOURCE -DVERSION='"$(VERSION)"' \
       -DPRESETDIR=$(call shell_word,"$(call c_text,$(DATADIR)/presets)") \
       -DLESSONDIR=$(call shell_word,"$(call c_text,$(DATADIR)/lessons)") \
       -DFIGLIBDIR=$(call shell_word,"$(call c_text,$(FIGLIBDIR))")

# Expanded when a recipe runs, after mk/deps.sh has made sure the packages are there.
CORE_PKGS = inih lapacke gsl fftw3
CORE_CFLAGS = $(shell $(PKG_CONFIG) --cflags $(CORE_PKGS))
# libunistring (Unicode's character classes, for escaping format characters) has no .pc.
CORE_LIBS = $(shell $(PKG_CONFIG) --libs $(CORE_PKGS)) -lunistring -lm
UI_CFLAGS = $(shell $(PKG_CONFIG) --cflags ncursesw)
UI_LIBS = $(shell $(PKG_CONFIG) --libs ncursesw)
# Figures and pixel charts: cairo draws and writes PNG, SVG and PDF; libsixel encodes sixel
# for terminals with fewer than 256 colour registers. GLib only for tests/sixelcheck.
FIG_PKGS = cairo fontconfig libsixel
FIG_CFLAGS = $(shell $(PKG_CONFIG) --cflags $(FIG_PKGS))
FIG_LIBS = $(shell $(PKG_CONFIG) --libs $(FIG_PKGS))
TEST_CFLAGS = $(shell $(PKG_CONFIG) --cflags cmocka)
TEST_LIBS = $(shell $(PKG_CONFIG) --libs cmocka)

CORE_SRC = $(wildcard src/core/*.c)
CORE_OBJ = $(CORE_SRC:src/%.c=$(BUILD)/%.o)
CORE_LIB = $(BUILD)/libspringsim-core.a
APP_SRC = $(wildcard src/app/*.c src/lab/*.c src/chart/*.c)
APP_OBJ = $(APP_SRC:src/%.c=$(BUILD)/%.o)
TUI_SRC = $(wildcard src/tui/*.c)
TUI_OBJ = $(TUI_SRC:src/%.c=$(BUILD)/%.o)
# The figure library (springsim-fig.so beside the program, loaded when a figure or a
# pixel plot is wanted: src/fig/lib.h) is every file of src/fig but the three the program
# keeps: the colours, a figure's data, the loader.
FIG_SRC = $(wildcard src/fig/*.c)
FIG_OBJ = $(FIG_SRC:src/%.c=$(BUILD)/%.o)
FIG_KEPT = $(BUILD)/fig/palette.o $(BUILD)/fig/report_data.o $(BUILD)/fig/load.o
FIG_SO_OBJ = $(filter-out $(FIG_KEPT),$(FIG_OBJ))
FIG_SO = $(dir $(BIN))springsim-fig.so
PLAIN_SRC = $(wildcard src/plain/*.c)
PLAIN_OBJ = $(PLAIN_SRC:src/%.c=$(BUILD)/%.o)
MAIN_OBJ = $(BUILD)/main.o $(BUILD)/run_headless.o $(BUILD)/run_tables.o $(BUILD)/run_batch.o \
    $(BUILD)/run_files.o $(BUILD)/run_nonlinear.o $(BUILD)/options.o $(BUILD)/lessons_cli.o \
    $(BUILD)/progress.o
TEST_SRC = $(wildcard tests/test_*.c)
TEST_BIN = $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)

COMPLETIONS = $(BUILD)/completions/springsim.bash $(BUILD)/completions/_springsim \
              $(BUILD)/completions/springsim.fish

.PHONY: all run check check-long sanitize valgrind bench fuzz install uninstall clean deps deps-test \
        completions docs deb FORCE

all: $(BIN) completions

run: $(BIN)
	./$(BIN)

$(BUILD)/.deps-build:
	@mkdir -p $(@D)
	@sh mk/deps.sh build
	@touch $@

$(BUILD)/.deps-test: | $(BUILD)/.deps-build
	@sh mk/deps.sh test
	@touch $@

deps: $(BUILD)/.deps-build
deps-test: $(BUILD)/.deps-test

# Below the terminal program nothing sees curses: the core, the app, the lab, the charts,
# the figures and the plain mode. This fails the build if one of their files includes it
# (or a tui header); they are compiled without the ncurses flags and the tests linked
# without -lncursesw.
PURE_DIRS = src/core src/app src/lab src/chart src/fig src/plain
$(BUILD)/.core-pure: $(wildcard $(PURE_DIRS:%=%/*.[ch])) | $(BUILD)/.deps-build
	@if grep -lE '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"](n?curses|ncursesw/|term\.h|\.\./tui/|tui/)' \
	    $(PURE_DIRS:%=%/*.[ch]); then \
	    echo "error: $(PURE_DIRS) must not include curses" >&2; \
	    exit 1; fi
	@touch $@

$(BUILD)/core/%.o: src/core/%.c | $(BUILD)/.core-pure
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(CORE_CFLAGS) -MMD -MP -c -o $@ $<

$(BUILD)/app/%.o: src/app/%.c | $(BUILD)/.core-pure
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(CORE_CFLAGS) -Isrc -MMD -MP -c -o $@ $<

$(BUILD)/lab/%.o: src/lab/%.c | $(BUILD)/.core-pure
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(CORE_CFLAGS) -Isrc -MMD -MP -c -o $@ $<

$(BUILD)/chart/%.o: src/chart/%.c | $(BUILD)/.core-pure
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(CORE_CFLAGS) -Isrc -MMD -MP -c -o $@ $<

$(BUILD)/fig/%.o: src/fig/%.c | $(BUILD)/.core-pure
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -fPIC $(WARN) $(DEFS) $(CPPFLAGS) $(CORE_CFLAGS) $(FIG_CFLAGS) -Isrc -MMD -MP \
	    -c -o $@ $<

$(BUILD)/plain/%.o: src/plain/%.c | $(BUILD)/.core-pure
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(CORE_CFLAGS) -Isrc -MMD -MP -c -o $@ $<

$(BUILD)/tui/%.o: src/tui/%.c | $(BUILD)/.deps-build
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(UI_CFLAGS) $(FIG_CFLAGS) -Isrc -MMD -MP -c \
	    -o $@ $<

$(MAIN_OBJ): $(BUILD)/%.o: src/%.c | $(BUILD)/.deps-build
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(UI_CFLAGS) $(CORE_CFLAGS) -Isrc -MMD -MP \
	    -c -o $@ $<

# The preset directory is compiled in: rebuild what uses it when PREFIX or DATADIR change.
$(BUILD)/.datadir: FORCE
	@mkdir -p $(@D)
	@printf '%s\n' $(call shell_word,$(DATADIR)) $(call shell_word,$(FIGLIBDIR)) | \
	    cmp -s - $@ || \
	    printf '%s\n' $(call shell_word,$(DATADIR)) $(call shell_word,$(FIGLIBDIR)) >$@
$(BUILD)/core/preset.o $(BUILD)/core/search.o $(BUILD)/main.o $(BUILD)/options.o \
    $(BUILD)/fig/load.o: $(BUILD)/.datadir
FORCE:

$(CORE_LIB): $(CORE_OBJ)
	rm -f $@
	$(AR) rcs $@ $^

# The program exports its symbols (-rdynamic) and holds the whole core: the figure library
# calls back into it (the core, the app, the charts) and is loaded with every symbol bound.
$(BIN): $(MAIN_OBJ) $(TUI_OBJ) $(PLAIN_OBJ) $(FIG_KEPT) $(APP_OBJ) $(CORE_LIB) $(FIG_SO)
	$(CC) $(CFLAGS) $(LDFLAGS) -rdynamic -o $@ $(MAIN_OBJ) $(TUI_OBJ) $(PLAIN_OBJ) $(FIG_KEPT) \
	    $(APP_OBJ) -Wl,--whole-archive $(CORE_LIB) -Wl,--no-whole-archive $(UI_LIBS) \
	    $(CORE_LIBS) -ldl

$(FIG_SO): $(FIG_SO_OBJ)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(LDFLAGS) -shared -o $@ $(FIG_SO_OBJ) $(FIG_LIBS) -lm

# The shell completions are written from the option table by a build tool on the core.
completions: $(COMPLETIONS)

$(BUILD)/mk/completions: mk/completions.c $(CORE_LIB)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(CORE_CFLAGS) -Isrc $(LDFLAGS) -o $@ $< \
	    $(CORE_LIB) $(CORE_LIBS)

# The README's and the man page's generated sections (keys, options, presets, the Debian
# packages) from the program's tables; tests/docs.sh fails in make check when one is stale.
$(BUILD)/mk/docgen: mk/docgen.c $(CORE_LIB)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(CORE_CFLAGS) -Isrc $(LDFLAGS) -o $@ $< \
	    $(CORE_LIB) $(CORE_LIBS)

docs: $(BIN) $(BUILD)/mk/docgen
	sh mk/docs.sh ./$(BIN) $(BUILD)/mk/docgen

$(BUILD)/completions/springsim.bash: SHELL_NAME = bash
$(BUILD)/completions/_springsim: SHELL_NAME = zsh
$(BUILD)/completions/springsim.fish: SHELL_NAME = fish
$(COMPLETIONS): $(BUILD)/mk/completions
	@mkdir -p $(@D)
	$(BUILD)/mk/completions $(SHELL_NAME) >$@.tmp && mv $@.tmp $@

# The app and the figures (no curses) are unit-tested like the core: every test links them.
$(TEST_BIN): $(APP_OBJ) $(FIG_OBJ)
$(TEST_BIN): TEST_EXTRA = $(APP_OBJ) $(FIG_OBJ)
# test_app, test_app_rules and test_ghost share a fixture that makes the chain's allocations
# fail on demand and counts the modes' computations (tests/app_fixture.c wraps them).
APP_WRAPPED = config_model sim_new history_new trail_new trail_new_motion sweep_new modes_compute \
              limits_modes
APP_TESTS = $(BUILD)/tests/test_app $(BUILD)/tests/test_app_rules $(BUILD)/tests/test_ghost \
            $(BUILD)/tests/test_export $(BUILD)/tests/test_controls $(BUILD)/tests/test_app_window
APP_FIXTURE = $(BUILD)/tests/app_fixture.o
$(APP_TESTS): TEST_LDFLAGS = $(APP_WRAPPED:%=-Wl,--wrap=%)
$(APP_TESTS): TEST_EXTRA += $(APP_FIXTURE)
$(APP_TESTS): $(APP_FIXTURE) tests/app_fixture.h
# test_ghost counts every allocation the app and the core make while the ghost runs, and
# test_spectrum those spectrum.c makes (FFTW's too), to see a step and a refresh make none
# (tests/alloc_count.c counts malloc, calloc and realloc).
ALLOC_COUNT = $(BUILD)/tests/alloc_count.o
ALLOC_WRAPPED = $(addprefix -Wl$(comma)--wrap=,malloc calloc realloc)
comma = ,
$(BUILD)/tests/test_ghost $(BUILD)/tests/test_spectrum $(BUILD)/tests/test_measure: TEST_EXTRA += $(ALLOC_COUNT)
$(BUILD)/tests/test_ghost $(BUILD)/tests/test_spectrum $(BUILD)/tests/test_measure: $(ALLOC_COUNT)
$(BUILD)/tests/test_ghost $(BUILD)/tests/test_measure: TEST_LDFLAGS += $(ALLOC_WRAPPED)
$(BUILD)/tests/test_spectrum: TEST_LDFLAGS = $(ALLOC_WRAPPED) \
    $(addprefix -Wl$(comma)--wrap=,fftw_malloc fftw_plan_dft_r2c_1d)

$(ALLOC_COUNT): tests/alloc_count.c tests/alloc_count.h | $(BUILD)/.deps-test
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) -c -o $@ $<

$(APP_FIXTURE): tests/app_fixture.c tests/app_fixture.h tests/testutil.h $(APP_OBJ) $(CORE_LIB) \
    | $(BUILD)/.deps-test
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(CORE_CFLAGS) $(TEST_CFLAGS) -Isrc \
	    -DSRCDIR='"$(CURDIR)"' -c -o $@ $<

$(BUILD)/tests/%: tests/%.c $(wildcard tests/*.h) $(CORE_LIB) | $(BUILD)/.deps-test
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(DEFS) $(CPPFLAGS) $(CORE_CFLAGS) $(TEST_CFLAGS) -Isrc \
	    -DSRCDIR='"$(CURDIR)"' $(TEST_LDFLAGS) -o $@ $< \
	    $(TEST_EXTRA) $(CORE_LIB) $(TEST_LIBS) $(FIG_LIBS) $(CORE_LIBS)

# A terminal that stops reading, for the fault tests: not a cmocka program.
$(BUILD)/tests/slowterm: tests/slowterm.c | $(BUILD)/.deps-build
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) -D_GNU_SOURCE $(LDFLAGS) -o $@ $< -lutil

# The pixel tests' terminal (answers the queries of a sixel, kitty or plain terminal)
# and the reader of the images it kept: not cmocka programs.
$(BUILD)/tests/pixterm: tests/pixterm.c | $(BUILD)/.deps-build
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) -D_GNU_SOURCE $(LDFLAGS) -o $@ $< -lutil
$(BUILD)/tests/sixelcheck: tests/sixelcheck.c | $(BUILD)/.deps-build
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(WARN) $(FIG_CFLAGS) $$($(PKG_CONFIG) --cflags glib-2.0) $(LDFLAGS) -o $@ $< \
	    $(FIG_LIBS) $$($(PKG_CONFIG) --libs glib-2.0)

# tests/deb.sh builds the Debian package (make deb) unless DEB_CHECK=no; SANITIZED=yes
# (make sanitize) tells the tests that memory and time figures are the sanitizer's.
DEB_CHECK ?= yes
SANITIZED ?= no
check: $(BIN) $(TEST_BIN) $(BUILD)/tests/slowterm $(BUILD)/tests/pixterm $(BUILD)/tests/sixelcheck \
    completions $(BUILD)/mk/docgen | $(BUILD)/.deps-test
	@SPRINGSIM=./$(BIN) SLOWTERM=$(BUILD)/tests/slowterm PIXTERM=$(BUILD)/tests/pixterm \
	    SIXELCHECK=$(BUILD)/tests/sixelcheck COMPLETIONS=$(BUILD)/completions \
	    DOCGEN=$(BUILD)/mk/docgen BUILD=$(BUILD) DEB_CHECK=$(DEB_CHECK) SANITIZED=$(SANITIZED) T="$(T)" TESTS="$(TESTS)" J="$(J)" \
	    sh tests/run.sh $(TEST_BIN)

# Everything again under AddressSanitizer and UndefinedBehaviorSanitizer.
SAN_FLAGS = -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
sanitize:
	@mkdir -p $(BUILD)/san && ln -sfn $(CURDIR)/presets $(BUILD)/san/presets && \
	    ln -sfn $(CURDIR)/lessons $(BUILD)/san/lessons
	$(MAKE) BUILD=$(BUILD)/san BIN=$(BUILD)/san/springsim CFLAGS="$(SAN_FLAGS)" \
	    LDFLAGS="$(SAN_FLAGS)" DEB_CHECK=no SANITIZED=yes check

# The unit tests and a headless run with collisions under valgrind's memcheck: zero
# errors and no definite leaks, or it fails.
VALGRIND = valgrind --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite \
           --quiet
valgrind: $(BIN) $(TEST_BIN)
	@command -v valgrind >/dev/null || sh mk/deps.sh valgrind
	@set -e; for t in $(TEST_BIN); do echo "== valgrind $$t"; CAMPAIGN_CASES=8 CAMPAIGN_MAXN=10 $(VALGRIND) $$t >/dev/null; done
	@echo "== valgrind --headless, collisions at resonance"
	@$(VALGRIND) ./$(BIN) --headless -p resonance --amplitude 0.6 --duration 60 --energy >/dev/null
	@$(VALGRIND) ./$(BIN) -p 3-mass-chain --modes >/dev/null
	@$(VALGRIND) ./$(BIN) -p 3-mass-chain --sweep 0.1:2:50 >/dev/null
	@echo "== valgrind --figure (cairo, fontconfig)"
	@$(VALGRIND) ./$(BIN) -p 3-mass-chain --sweep 0.1:2:50 --figure $(BUILD)/valgrind.png >/dev/null
	@$(VALGRIND) ./$(BIN) --headless --duration 2 --figure $(BUILD)/valgrind.svg >/dev/null
	@echo "valgrind: no errors, no definite leaks"

# The long fault tests: a 1e8-step soak, a resize storm of hundreds of sizes.
check-long: $(BIN) | $(BUILD)/.deps-test
	@SPRINGSIM=./$(BIN) sh tests/long/soak.sh
	@SPRINGSIM=./$(BIN) sh tests/long/storm.sh
	@SPRINGSIM=./$(BIN) sh tests/long/modes.sh

# Speed and cost, side by side in one run: the core against GSL's rk4, cost per mass, CSV
# rate, and the interactive program in a pseudo-terminal.
BENCH_SECONDS ?= 10
bench: $(BIN) $(CORE_LIB) | $(BUILD)/.deps-build
	@sh mk/deps.sh bench
	@mkdir -p $(BUILD)/bench
	@$(CC) -O2 -g $(DEFS) $(CORE_CFLAGS) -Isrc -o $(BUILD)/bench/bench_core \
	    tests/bench/bench_core.c $(CORE_LIB) $$($(PKG_CONFIG) --cflags --libs gsl) $(CORE_LIBS)
	@$(CC) -O2 -g -D_GNU_SOURCE -o $(BUILD)/bench/bench_tty tests/bench/bench_tty.c -lutil
	@$(CC) -O2 -g -o $(BUILD)/bench/bench_procs tests/bench/bench_procs.c
	@$(CC) -O2 -g -o $(BUILD)/bench/anchor_plain tests/bench/anchor_plain.c -lm
	@$(CC) -O2 -g -o $(BUILD)/bench/anchor_gsl tests/bench/anchor_gsl.c \
	    $$($(PKG_CONFIG) --cflags --libs gsl)
	@echo "whole processes, N = 5, dt = 0.001, 3e6 steps, CPU time, medians of $${BENCH_ROUNDS:-5} alternated"
	@echo "(goals: GSL's rk4 driver >= 4.5x springsim's time; the plain loop >= 1.0x with"
	@echo "collisions on, >= 1.1x with them off)"
	@echo
	@echo "| process | CPU | time / springsim's |"
	@echo "| --- | --- | --- |"
	@$(BUILD)/bench/bench_procs 'springsim --headless, collisions on' -- \
	    ./$(BIN) --headless -n 5 --dt 0.001 --duration 3000 --sample 3000 -- \
	    'springsim --headless --no-collisions' -- \
	    ./$(BIN) --headless -n 5 --dt 0.001 --duration 3000 --sample 3000 --no-collisions -- \
	    'plain RK4 loop (anchor_plain.c)' -- $(BUILD)/bench/anchor_plain 5 0.001 3000000 -- \
	    'GSL rk4, fixed-step driver (anchor_gsl.c)' -- $(BUILD)/bench/anchor_gsl 5 0.001 3000000
	@echo
	@echo "the damped modes of 300 masses, the left half damped (goal: under 2 s of CPU)"
	@echo
	@$(BUILD)/bench/bench_procs '--modes -n 300, half damped' -- ./$(BIN) --modes -n 300 \
	    --spring 10 --boundary wall --damping \
	    $$(awk 'BEGIN { for (i = 1; i <= 300; i++) printf "%s%s", (i > 1 ? "," : ""), (i <= 150 ? 2 : 0) }')
	@echo
	@echo "start-up, --headless --duration 0 (goals: N = 10 under 15 ms of CPU, N = 1000 under"
	@echo "100 ms)"
	@echo
	@echo "| process | CPU | time / N = 10's |"
	@echo "| --- | --- | --- |"
	@$(BUILD)/bench/bench_procs 'springsim --headless --duration 0 -n 10' -- \
	    ./$(BIN) --headless --duration 0 -n 10 -- \
	    'springsim --headless --duration 0 -n 1000' -- ./$(BIN) --headless --duration 0 -n 1000
	@echo
	@$(BUILD)/bench/bench_core
	@echo
	@echo "interactive program, running $(BENCH_SECONDS) s after space (goals at 120x40:"
	@echo "CPU < 1.5 %, output < 100 KB/s, first frame < 30 ms, RSS < 10 MB; also < 100 KB/s at"
	@echo "200x60, with a plot enlarged and in the spectrum view; also < 3 % and < 100 KB/s"
	@echo "with the ghost on (g) parting from the chain and in the modes and response views;"
	@echo "low bandwidth < 20 KB/s)"
	@echo
	@echo "| run | size | CPU | output | first frame | peak RSS |"
	@echo "| --- | --- | --- | --- | --- | --- |"
	@$(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) default ./$(BIN)
	@$(BUILD)/bench/bench_tty 200 60 $(BENCH_SECONDS) default ./$(BIN)
	@BENCH_KEYS='1 ' $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) 'plot 1 enlarged' ./$(BIN)
	@BENCH_KEYS='1 ' $(BUILD)/bench/bench_tty 200 60 $(BENCH_SECONDS) 'plot 1 enlarged' ./$(BIN)
	@BENCH_KEYS='F ' $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) 'spectrum view (F)' ./$(BIN)
	@BENCH_KEYS='F]]]] ' $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) \
	    'spectrum view, 10x (a 60 s record)' ./$(BIN)
	@BENCH_KEYS="gjjjj$$(printf '\033[5~\033[5~\033[5~\033[5~\033[5~') " \
	    $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) \
	    'ghost (g), damping 0.1 to 0.6' ./$(BIN)
	@BENCH_KEYS='m ' $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) 'modes view (m), swinging' \
	    ./$(BIN)
	@BENCH_KEYS='f ' $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) 'response view (f), phase' \
	    ./$(BIN)
	@$(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) --low-bandwidth ./$(BIN) --low-bandwidth
	@$(BUILD)/bench/bench_tty 200 60 $(BENCH_SECONDS) --low-bandwidth ./$(BIN) --low-bandwidth
	@echo
	@echo "pixel graphics (goals: sixel < 300 KB/s and CPU < 6 % at 120x40, < 600 KB/s at 80x24;"
	@echo "kitty < 400 KB/s at 120x40; cells of 10x20 pixels; first frame < 30 ms with auto"
	@echo "in a terminal that never answers, which gets braille)"
	@echo
	@echo "| run | size | CPU | output | first frame | peak RSS |"
	@echo "| --- | --- | --- | --- | --- | --- |"
	@BENCH_TERM=sixel $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) sixel ./$(BIN)
	@BENCH_TERM=sixel $(BUILD)/bench/bench_tty 80 24 $(BENCH_SECONDS) sixel ./$(BIN)
	@BENCH_TERM=sixel BENCH_KEYS='1 ' $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) \
	    'sixel, plot 1 enlarged' ./$(BIN)
	@BENCH_TERM=sixel BENCH_KEYS='m ' $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) \
	    'sixel, modes view (m), swinging' ./$(BIN)
	@BENCH_TERM=kitty $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) kitty ./$(BIN)
	@BENCH_TERM=kitty $(BUILD)/bench/bench_tty 80 24 $(BENCH_SECONDS) kitty ./$(BIN)
	@BENCH_TERM=none $(BUILD)/bench/bench_tty 120 40 $(BENCH_SECONDS) \
	    'auto, a terminal that never answers' ./$(BIN)

# Fuzzing with clang's libFuzzer under ASan + UBSan: make fuzz FUZZ_SECONDS=N runs each
# target N seconds from its seed corpus (a copy: what it finds stays in build/fuzz).
FUZZ_SECONDS ?= 60
FUZZ_CC = clang
FUZZ_FLAGS = -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
FUZZ_SRC = $(CORE_SRC) src/options.c src/tui/input.c
FUZZ_TARGETS = preset options

fuzz: | $(BUILD)/.deps-build
	@sh mk/deps.sh fuzz
	@mkdir -p $(BUILD)/fuzz
	@set -e; for t in $(FUZZ_TARGETS); do \
	    $(FUZZ_CC) $(FUZZ_FLAGS) $(DEFS) $(CORE_CFLAGS) $(UI_CFLAGS) -Isrc \
	        -o $(BUILD)/fuzz/fuzz_$$t tests/fuzz/fuzz_$$t.c $(FUZZ_SRC) $(CORE_LIBS); \
	    rm -rf $(BUILD)/fuzz/corpus-$$t; cp -r tests/fuzz/corpus-$$t $(BUILD)/fuzz/; \
	    echo "== fuzz_$$t: $(FUZZ_SECONDS) s"; \
	    if $(BUILD)/fuzz/fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -timeout=10 \
	        -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
	        -artifact_prefix=$(BUILD)/fuzz/$$t- $(BUILD)/fuzz/corpus-$$t tests/fuzz/regressions \
	        >$(BUILD)/fuzz/$$t.log 2>&1; then \
	        grep -E '^stat::(number_of_executed_units|average_exec_per_sec)' $(BUILD)/fuzz/$$t.log; \
	    else \
	        grep -E '==[0-9]+==ERROR|SUMMARY|Test unit written' $(BUILD)/fuzz/$$t.log; \
	        echo "fuzz_$$t found a problem: see $(BUILD)/fuzz/$$t.log"; exit 1; \
	    fi; \
	done

# Every path goes to the shell through the environment and is quoted there, so that a
# DESTDIR or PREFIX with blanks, quotes or any other byte names one directory (issue 23).
# uninstall removes exactly the files install puts, then the directories it made if they
# are left empty: nothing else, not even a preset of someone else's beside ours.
INSTALL_DIRS = SS_BINDIR='$(subst ','\'',$(DESTDIR)$(BINDIR))' \
    SS_MANDIR='$(subst ','\'',$(DESTDIR)$(MANDIR))' \
    SS_DATADIR='$(subst ','\'',$(DESTDIR)$(DATADIR))' \
    SS_BASHCOMPDIR='$(subst ','\'',$(DESTDIR)$(BASHCOMPDIR))' \
    SS_ZSHCOMPDIR='$(subst ','\'',$(DESTDIR)$(ZSHCOMPDIR))' \
    SS_FISHCOMPDIR='$(subst ','\'',$(DESTDIR)$(FISHCOMPDIR))' \
    SS_FIGLIBDIR='$(subst ','\'',$(DESTDIR)$(FIGLIBDIR))' SS_FIG_SO='$(subst ','\'',$(FIG_SO))' \
    SS_BIN='$(subst ','\'',$(BIN))' SS_BUILD='$(subst ','\'',$(BUILD))'

install: $(BIN) completions
	@$(INSTALL_DIRS); set -e; \
	install -d "$$SS_BINDIR" "$$SS_MANDIR" "$$SS_DATADIR/presets" "$$SS_DATADIR/lessons" \
	    "$$SS_BASHCOMPDIR" "$$SS_ZSHCOMPDIR" "$$SS_FISHCOMPDIR" "$$SS_FIGLIBDIR"; \
	install -m 755 "$$SS_BIN" "$$SS_BINDIR/springsim"; \
	install -m 644 "$$SS_FIG_SO" "$$SS_FIGLIBDIR/springsim-fig.so"; \
	install -m 644 man/springsim.1 "$$SS_MANDIR/springsim.1"; \
	install -m 644 presets/*.ini "$$SS_DATADIR/presets/"; \
	install -m 644 lessons/*.lesson "$$SS_DATADIR/lessons/"; \
	install -m 644 "$$SS_BUILD/completions/springsim.bash" "$$SS_BASHCOMPDIR/springsim"; \
	install -m 644 "$$SS_BUILD/completions/_springsim" "$$SS_ZSHCOMPDIR/_springsim"; \
	install -m 644 "$$SS_BUILD/completions/springsim.fish" "$$SS_FISHCOMPDIR/springsim.fish"

uninstall:
	@$(INSTALL_DIRS); set -e; \
	rm -f "$$SS_BINDIR/springsim" "$$SS_MANDIR/springsim.1" \
	    "$$SS_BASHCOMPDIR/springsim" "$$SS_ZSHCOMPDIR/_springsim" \
	    "$$SS_FISHCOMPDIR/springsim.fish" "$$SS_FIGLIBDIR/springsim-fig.so"; \
	rmdir "$$SS_FIGLIBDIR" 2>/dev/null || true; \
	for f in presets/*.ini lessons/*.lesson; do rm -f "$$SS_DATADIR/$$f"; done; \
	rmdir "$$SS_DATADIR/presets" "$$SS_DATADIR/lessons" "$$SS_DATADIR" 2>/dev/null || true

# An unsigned Debian package (debian/, dh with debhelper compat 13), built from a copy of
# the tree in $(BUILD)/deb so that its clean step leaves this build alone; the .deb is
# copied to $(BUILD)/ and lintian must find no error in it (its warnings are shown).
DEB_DIR = $(BUILD)/deb
deb: | $(BUILD)/.deps-build
	@sh mk/deps.sh deb
	@v=$$(dpkg-parsechangelog -S Version); [ "$$v" = "$(VERSION)" ] || \
	    { echo "make deb: debian/changelog is at $$v, the Makefile at $(VERSION)" >&2; exit 1; }
	@rm -rf $(DEB_DIR) && mkdir -p $(DEB_DIR)/springsim-$(VERSION)
	@tar -cf - --exclude=./build --exclude=./$(BUILD) --exclude=./.git --exclude=./springsim . | \
	    tar -xf - -C $(DEB_DIR)/springsim-$(VERSION)
	@echo "dpkg-buildpackage -us -uc -b in $(DEB_DIR)/springsim-$(VERSION) (log: $(DEB_DIR)/build.log)"
	@cd $(DEB_DIR)/springsim-$(VERSION) && \
	    if ! env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL dpkg-buildpackage -us -uc -b \
	        >../build.log 2>&1; then tail -n 30 ../build.log; exit 1; fi
	@cp $(DEB_DIR)/springsim_$(VERSION)_*.deb $(BUILD)/
	@echo "lintian $(DEB_DIR)/springsim_$(VERSION)_*.changes"
	@lintian --fail-on error $(DEB_DIR)/springsim_$(VERSION)_*.changes
	@ls $(BUILD)/springsim_$(VERSION)_*.deb

clean:
	rm -rf $(BUILD) springsim springsim-fig.so

-include $(CORE_OBJ:.o=.d) $(APP_OBJ:.o=.d) $(FIG_OBJ:.o=.d) $(TUI_OBJ:.o=.d) $(PLAIN_OBJ:.o=.d) $(MAIN_OBJ:.o=.d)
