#!/usr/bin/env bash
# Writes the `# error:` (and `# note:`) header of a malformed test scene from what glint says of
# it, for tests/scene/bad/. Usage: stamp-bad-scene.sh GLINT FILE...  (the file's YAML without a
# header). Read every header it writes: the message must be the one the case is for.
set -euo pipefail
glint=$1
shift
for f in "$@"; do
    body=$(grep -v '^# error: \|^# note: ' "$f")
    printf '%s\n' "$body" > "$f"
    notes=$("$glint" render "$f" -o "${TMPDIR:-/tmp}/stamp-bad-scene.png" 2>&1 | grep -c '^note:' || true)
    { echo "# error: x"; for ((i = 0; i < notes; i++)); do echo "# note: x"; done; printf '%s\n' "$body"; } > "$f"
    out=$("$glint" render "$f" -o "${TMPDIR:-/tmp}/stamp-bad-scene.png" 2>&1 || true)
    first=$(printf '%s\n' "$out" | head -1)
    location_message=${first#"$f":}
    location_message=${location_message/ error: / }
    { echo "# error: $location_message"
      printf '%s\n' "$out" | { grep '^note: ' || true; } | sed 's/^note: /# note: /'
      printf '%s\n' "$body"; } > "$f"
done
