# Sourced by the scripts that make Debian roots: make_debian_root SUITE TARGET [MMDEBSTRAP_OPTION...]
# makes one from Debian's packages through the host's mirror, whose Release files, frozen, are
# past their Valid-Until date.
make_debian_root() {
  local suite=$1 target=$2 mirror
  shift 2
  command -v mmdebstrap > /dev/null || { apt-get update -q && apt-get install -y -q mmdebstrap; }
  mirror=$(awk '/^URIs:/ {print $2; exit}' /etc/apt/sources.list.d/debian.sources 2>/dev/null || true)
  mmdebstrap --variant=apt --aptopt='Acquire::Check-Valid-Until "false"' "$@" "$suite" "$target" \
    ${mirror:+"$mirror"}
}
