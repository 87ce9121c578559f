#!/usr/bin/env bash
# Install the Debian packages stickslip's environment needs, only if missing.
#   libblas3, liblapack3: shared libraries of openseespy (the test oracle).
set -euo pipefail

missing=()
for lib in libblas.so.3 liblapack.so.3; do
    ldconfig -p | grep -q "$lib" || missing+=("$lib")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "installing system packages libblas3 liblapack3 (missing: ${missing[*]})"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq libblas3 liblapack3
