"""Pure mechanics of the voussoir arch: geometry, joint kinematics, the joint law, hinges, units (no YADE)."""
