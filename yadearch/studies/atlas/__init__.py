"""The atlas: the collapse of five arch shapes under six support movements, over thickness and joint
stiffness, in the static engine, the rigid march and (a subset) the DEM, side by side (docs/atlas.md)."""
