#!/usr/bin/env bash
# Install the Debian packages stickslip's tests need, only if missing
# (`make test` runs this; `make reproduce` does not need it, nor root).
#   libblas3, liblapack3: shared libraries of openseespy (the test oracle);
#   libudunits2-0: the UDUNITS-2 library of cfchecker (the CF checker of the tests).
set -euo pipefail

# The linker cache is read once into a variable and then searched: a pipeline
# `ldconfig -p | grep -q` under pipefail fails now and then, when grep exits at
# its first match and ldconfig, still writing, dies of SIGPIPE.
cache=$(PATH="$PATH:/sbin:/usr/sbin" ldconfig -p)
# shared library -> the Debian package that provides it
declare -A packages=([libblas.so.3]=libblas3 [liblapack.so.3]=liblapack3 [libudunits2.so.0]=libudunits2-0)
missing=()
for lib in "${!packages[@]}"; do
    [[ $cache == *"$lib "* ]] || missing+=("${packages[$lib]}")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "installing system packages ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}"
