#!/usr/bin/env bash
# The shipped NAO URDFs are exactly what make_urdf.py writes, so an edit to either shows.
set -euo pipefail
dir=$1/scenes/robots/nao
python3 "$dir/make_urdf.py" | cmp - "$dir/nao.urdf"
python3 "$dir/make_urdf.py" --sole-contact-width 0.075 | cmp - "$dir/nao_rounded_sole.urdf"
