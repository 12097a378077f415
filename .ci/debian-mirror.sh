# Sourced by scripts that fetch from Debian: prints the Debian archive this machine's own apt
# sources use (deb822 .sources or one-line lists), the first URI of an entry for the main archive,
# not its security suites; DEBIAN_MIRROR overrides it. Prints nothing when there is none. No
# address is written here: a machine behind its own mirror keeps using it.
debian_mirror() {
  if [ -n "${DEBIAN_MIRROR:-}" ]; then
    echo "$DEBIAN_MIRROR"
    return
  fi
  local f
  {
    for f in /etc/apt/sources.list.d/*.sources; do
      [ -f "$f" ] || continue
      awk 'BEGIN { RS = ""; FS = "\n" }
           { uris = ""; suites = ""
             for (i = 1; i <= NF; i++) {
               if ($i ~ /^URIs:/) { sub(/^URIs:[ \t]*/, "", $i); split($i, u, /[ \t]+/); uris = u[1] }
               if ($i ~ /^Suites:/) suites = $i
             }
             if (uris != "" && suites !~ /-security/ && uris ~ /debian\/?$/) { print uris; exit } }' "$f"
    done
    for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
      [ -f "$f" ] || continue
      awk '$1 == "deb" && $0 !~ /-security/ { sub(/\[[^]]*\]/, ""); $0 = $0; if ($2 ~ /debian\/?$/) print $2 }' "$f"
    done
  } | sed -n 1p  # reads everything: under pipefail, head would leave a writer killed by SIGPIPE
}
