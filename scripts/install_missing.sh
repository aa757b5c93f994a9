#!/usr/bin/env bash
# Installs the Debian packages named that are not installed yet, with apt-get (as root, or
# through sudo); says which first. The setup scripts' one way to install.
#   scripts/install_missing.sh WHO PACKAGE...   (WHO names the script in the message)
set -euo pipefail
who=$1
shift
missing=()
for package in "$@"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
((${#missing[@]})) || exit 0
echo "$who: installing ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then sudo=(); else sudo=(sudo); fi
"${sudo[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
