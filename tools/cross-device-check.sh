#!/usr/bin/env bash
# The cross-device check of docs/devices.md: every shipped scene rendered at 320x180 on two Vulkan devices
# must agree to PSNR >= 35 dB with at most 1 % of pixels more than 8/255 apart.
#
#   tools/cross-device-check.sh render DIR [LAGOON]       render every scenes/*.json on the device that
#                                                         LAGOON_DEVICE picks (default: the best one) into
#                                                         DIR/<scene>.png, and DIR/device.txt (lagoon info)
#   tools/cross-device-check.sh compare DIR_A DIR_B [LAGOON]
#                                                         compare the two sets; exit 1 if any scene fails
#   tools/cross-device-check.sh both DEVICE_A DEVICE_B    both on this machine (device index or name part)
#
# LAGOON defaults to build/bin/lagoon. On a GPU machine without Debian's libraries, run the render step
# through ../shared/tools/gpu/pack.sh's kit and bring DIR back (docs/devices.md says how).
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }

render() {
  local dir=$1 lagoon=${2:-build/bin/lagoon}
  mkdir -p "$dir"
  "$lagoon" info > "$dir/device.txt"
  for scene in scenes/*.json; do
    local name
    name=$(basename "$scene" .json)
    "$lagoon" render --scene "$scene" --width 320 --height 180 --out "$dir/$name.png" > /dev/null
    echo "rendered $name on $(head -1 "$dir/device.txt")"
  done
}

compare() {
  local a=$1 b=$2 lagoon=${3:-build/bin/lagoon} failed=0
  for png in "$a"/*.png; do
    local name
    name=$(basename "$png")
    if [ ! -f "$b/$name" ]; then
      echo "$name: missing in $b" >&2
      failed=1
      continue
    fi
    echo "== $name"
    # compare-images' defaults are the agreement (io::kDeviceAgreement).
    "$lagoon" compare-images "$png" "$b/$name" || failed=1
  done
  return $failed
}

case "${1:-}" in
  render) [ $# -ge 2 ] || usage; render "$2" "${3:-}" ;;
  compare) [ $# -ge 3 ] || usage; compare "$2" "$3" "${4:-}" ;;
  both)
    [ $# -eq 3 ] || usage
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    LAGOON_DEVICE=$2 render "$tmp/a"
    LAGOON_DEVICE=$3 render "$tmp/b"
    compare "$tmp/a" "$tmp/b"
    ;;
  *) usage ;;
esac
