#!/bin/bash
# Dome master: config/walls/dome-180.toml (a 512x512 angular fisheye cut into two halves, one per
# rank) rendered on 2 ranks and gathered equals its --single-screen render bit for bit, since every
# pixel's ray comes from its canvas position alone; the pixels outside the image circle are black.
# Scene: the ground observer at 65 N looking at the zenith.
source "$(dirname "$0")/lib.sh"

wall="$WALLS/dome-180.toml"
cat > "$WORK/zenith.toml" <<TOML
[scene]
base = "$SRC_DIR/config/scenes/ground-65n.toml"
name = "ground observer 65N, zenith"

[camera]
latitude_deg = 65.0
longitude_deg = 20.0
altitude_km = 0.3
heading_deg = 0.0
elevation_deg = 90.0
TOML

note "dome-180: 2 ranks, --gather --tiles"
aw_mpirun 2 render --wall "$wall" --scene "$WORK/zenith.toml" --gather --tiles --quiet --out "$WORK/wall"
note "dome-180: --single-screen on 1 rank"
aw_mpirun 1 render --wall "$wall" --scene "$WORK/zenith.toml" --single-screen --gather --quiet --out "$WORK/single"
"$COMPARE" content "$WORK/single/wall.exr" "$wall" --min-max 1e-3 --lit-above 5e-4 --min-lit-screens 2
"$COMPARE" diff "$WORK/single/wall.exr" "$WORK/wall/wall.exr"
"$COMPARE" tiles "$wall" "$WORK/single/wall.exr" "$WORK/wall"
"$COMPARE" dome "$wall" "$WORK/wall/wall.exr"
echo "PASS dome"
