"""Above both engines: launch one run in its own process with the engine its case names (the DEM's
YADE child, or a static worker) and report its outcome; neither engine imports the other."""
