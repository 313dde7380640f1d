"""The only layer that imports YADE: the scene, the contact models, stepping and the loading protocol."""
