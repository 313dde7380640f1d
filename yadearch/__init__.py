"""yadearch: masonry arches on moving supports, simulated with YADE's polyhedral discrete elements."""

__version__ = "0.1.0"
