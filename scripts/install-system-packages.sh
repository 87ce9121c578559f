#!/usr/bin/env bash
# Install the Debian packages stickslip's tests need, only if missing
# (`make test` runs this; `make reproduce` does not need it, nor root).
#   libblas3, liblapack3: shared libraries of openseespy (the test oracle).
set -euo pipefail

# The linker cache is read once into a variable and then searched: a pipeline
# `ldconfig -p | grep -q` under pipefail fails now and then, when grep exits at
# its first match and ldconfig, still writing, dies of SIGPIPE.
cache=$(PATH="$PATH:/sbin:/usr/sbin" ldconfig -p)
missing=()
for lib in libblas.so.3 liblapack.so.3; do
    [[ $cache == *"$lib "* ]] || missing+=("$lib")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "installing system packages libblas3 liblapack3 (missing: ${missing[*]})"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq libblas3 liblapack3
