#!/usr/bin/env bash
# Installs the Debian packages (if missing) and builds the package in .ws/.
set -euo pipefail
source "$(dirname "$0")/common.sh"
rbs_install_packages
rbs_build
