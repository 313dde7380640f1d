"""Fonts embedded in a figure's PDF without their OpenType layout tables.

matplotlib embeds each TrueType font a PDF uses (`pdf.fonttype` 42) as a subset made by fontTools, which
keeps the font's layout tables (GSUB, GPOS, GDEF, MATH) and so decompiles and prunes them: most of the
time a PDF of the house style takes to write (docs/speed.md). Nothing reads them: matplotlib places every
glyph itself (kerning from the full font), and a PDF viewer draws a glyph from its outline and the width
the PDF states. Dropped, the PDF holds the same glyph outlines, widths, hinting and character map. The
function it stands in for is matplotlib's own, private one: where its signature is not the one this
replaces (matplotlib 3.11 subsets by glyph index), PDFs are written by matplotlib's as they are.
"""

from __future__ import annotations

import inspect
from collections.abc import Iterator
from contextlib import contextmanager
from io import BytesIO

from fontTools import subset
from matplotlib.backends import _backend_pdf_ps

LAYOUT_TABLES = ("GSUB", "GPOS", "GDEF", "MATH")  # OpenType layout: shaping and math layout, unused in a PDF
MATPLOTLIB_DROPPED = ("FFTM", "PfEd", "BDF")  # the tables matplotlib's own subsetting drops
COLLECTION_SUFFIX = ".ttc"  # a font collection: its first font, as matplotlib takes it
REPLACED_SIGNATURE = ("fontfile", "characters")  # matplotlib's get_glyphs_subset that `glyph_subset` stands in for


def glyph_subset(fontfile: str, characters: str) -> BytesIO:
    """The font `fontfile` cut to `characters` as matplotlib's `get_glyphs_subset` cuts it (glyph names
    and the recommended glyphs kept), without the layout tables; the font file's bytes."""
    options = subset.Options(glyph_names=True, recommended_glyphs=True)
    options.drop_tables += [*MATPLOTLIB_DROPPED, *LAYOUT_TABLES]
    if fontfile.endswith(COLLECTION_SUFFIX):
        options.font_number = 0
    with subset.load_font(fontfile, options) as font:
        subsetter = subset.Subsetter(options=options)
        subsetter.populate(text=characters)
        subsetter.subset(font)
        data = BytesIO()
        font.save(data, reorderTables=False)
        return data


def lean_fonts_apply() -> bool:
    """Whether this matplotlib subsets fonts by the function `glyph_subset` stands in for."""
    original = getattr(_backend_pdf_ps, "get_glyphs_subset", None)
    return original is not None and tuple(inspect.signature(original).parameters) == REPLACED_SIGNATURE


@contextmanager
def lean_pdf_fonts() -> Iterator[None]:
    """Within the block, PDFs matplotlib writes embed their fonts by `glyph_subset` (where it applies,
    `lean_fonts_apply`; elsewhere by matplotlib's own subsetting)."""
    if not lean_fonts_apply():
        yield
        return
    original = _backend_pdf_ps.get_glyphs_subset
    _backend_pdf_ps.get_glyphs_subset = glyph_subset
    try:
        yield
    finally:
        _backend_pdf_ps.get_glyphs_subset = original
