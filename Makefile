# offsetlab: two commands from a fresh clone.
#   make serve  installs what is missing, builds the wasm, serves www/ on
#               http://127.0.0.1:8000/ (PORT=... to change)
#   make test   installs what is missing and runs every test layer
SHELL := bash
.SHELLFLAGS := -eu -o pipefail -c
.NOTPARALLEL:
.DEFAULT_GOAL := help

# scripts/setup.sh puts a Node.js from PyPI there when the system's is too old.
export PATH := $(HOME)/.cargo/bin:$(HOME)/.local/share/offsetlab/node/bin:$(PATH)
PORT ?= 8000
CHROMEDRIVER ?= /usr/bin/chromedriver
TIMED := scripts/timed.sh

.PHONY: help setup wasm page cli serve test reset-logs lint test-native test-oracle test-wasm test-e2e clean

help:
	@echo "make serve   install what is missing, build, serve http://127.0.0.1:$(PORT)/"
	@echo "make test    install what is missing, run every test layer"
	@echo "make bench-browser  measure issue 6's browser targets 3-5 (BENCH_ARGS=\"--runs 5\" …)"

setup:
	@$(TIMED) setup bash scripts/setup.sh

# The page's wasm package (www/pkg, generated, not committed).
# wasm-pack's own wasm-opt would download binaryen (off in Cargo.toml); binaryen's
# wasm-opt from npm (package.json) optimises the module instead: the page's runs
# take about a quarter less time (docs/performance.md).
wasm: setup
	@$(TIMED) wasm-build wasm-pack build --target web --out-dir www/pkg
	@$(TIMED) wasm-opt bash scripts/wasm-opt.sh

# The page's CodeMirror bundle (www/dist, generated, not committed).
page: setup
	@$(TIMED) page-build npm run --silent build:page

# The CLI the end-to-end tests run to make and read links (target/debug/offsetlab).
cli: setup
	@$(TIMED) cli-build cargo build --bin offsetlab

serve: wasm page
	node scripts/serve.mjs --port $(PORT)

test: reset-logs setup lint test-native test-oracle test-wasm wasm page test-e2e
	@bash scripts/summary.sh

reset-logs:
	@rm -rf test-results/logs

lint: setup
	@$(TIMED) fmt cargo fmt --check
	@$(TIMED) clippy cargo clippy --all-targets -- -D warnings
	@$(TIMED) clippy-wasm cargo clippy --target wasm32-unknown-unknown --lib --test wasm -- -D warnings

# Parser, machine, renderer and CLI contract, natively.
test-native: setup
	@$(TIMED) native cargo test

# The linuxcnc profile against LinuxCNC's own interpreter, rs274 (behaviour
# 22): every program of tests/linuxcnc moves as rs274 moves it, and each of
# tests/linuxcnc/refused is refused by both. Fails, never skips, without rs274.
test-oracle: setup cli
	@$(TIMED) oracle-setup bash scripts/setup.sh --oracle
	@$(TIMED) oracle python3 scripts/oracle-linuxcnc.py --offsetlab target/debug/offsetlab --ignore-zero-length tests/linuxcnc tests/linuxcnc/refused

# The wasm contract: the same core in headless Chromium, JS shape pinned.
test-wasm: setup
	@$(TIMED) wasm-contract wasm-pack test --headless --chrome --chromedriver $(CHROMEDRIVER) -- --test wasm

# The page end to end in headless Chromium (needs www/pkg: make wasm; runs the CLI).
test-e2e: setup page cli
	@$(TIMED) e2e npm run --silent test:e2e

clean:
	rm -rf www/pkg www/dist test-results

# Browser benchmark of issue 6's targets 3–5 (headless Chromium; prints a
# table and never fails the build; not part of make test). Options in
# BENCH_ARGS, e.g. BENCH_ARGS="--runs 5 --json"; see scripts/bench-browser.mjs.
.PHONY: bench-browser
bench-browser: setup wasm page
	node scripts/bench-browser.mjs $(BENCH_ARGS)
