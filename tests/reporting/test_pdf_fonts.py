"""A figure's PDF embeds its fonts without their layout tables (plotting.pdf_fonts): the same glyph
outlines, advance widths and character map as matplotlib's own subset, which keeps GSUB, GPOS, GDEF
and MATH; and the figure's drawing in the PDF is unchanged."""

from __future__ import annotations

import re
import zlib
from pathlib import Path

import matplotlib
import pytest
from fontTools.ttLib import TTFont
from matplotlib import font_manager
from matplotlib.backends import _backend_pdf_ps

from yadearch.plotting.house import STYLE, new_figure, save_figure
from yadearch.plotting.pdf_fonts import LAYOUT_TABLES, glyph_subset, lean_fonts_apply, lean_pdf_fonts

needs_lean_fonts = pytest.mark.skipif(
    not lean_fonts_apply(), reason="this matplotlib subsets fonts otherwise: its own subsetting writes the PDFs"
)
TEXT = r"0123456789.,()-=: reaction (N) settlement δ"


@needs_lean_fonts
def test_the_lean_subset_draws_the_same_glyphs() -> None:
    path = font_manager.findfont("DejaVu Sans")
    lean, full = TTFont(glyph_subset(path, TEXT)), TTFont(_backend_pdf_ps.get_glyphs_subset(path, TEXT))
    assert not set(LAYOUT_TABLES) & set(lean.keys()) and set(LAYOUT_TABLES) & set(full.keys())
    assert lean.getBestCmap() == full.getBestCmap()
    for glyph in set(lean.getBestCmap().values()):
        assert lean["glyf"][glyph].compile(lean["glyf"]) == full["glyf"][glyph].compile(full["glyf"])
        assert lean["hmtx"][glyph] == full["hmtx"][glyph]
    # the glyphs keep their numbers: the PDF's character-to-glyph map is the same
    assert [lean.getGlyphID(g) for g in lean.getBestCmap().values()] == [
        full.getGlyphID(g) for g in full.getBestCmap().values()
    ]


def _page_content(pdf: Path) -> list[bytes]:
    """The PDF's decompressed streams but its embedded font files."""
    data = pdf.read_bytes()
    fonts = set(re.findall(rb"/FontFile2 (\d+) 0 R", data))
    objects = re.finditer(rb"(?m)^(\d+) 0 obj\n(.*?)^endobj", data, re.S)
    streams = [(m[1], re.search(rb"(?s)stream\n(.*)\nendstream", m[2])) for m in objects]
    return [zlib.decompress(stream[1]) for number, stream in streams if stream and number not in fonts]


@needs_lean_fonts
def test_a_figure_pdf_is_drawn_the_same_with_lean_fonts(tmp_path: Path) -> None:
    fig = new_figure(height_cm=5.0)
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 2], label="left support")
    ax.set_xlabel(r"settlement $\delta$ (mm)")
    ax.legend()
    full = tmp_path / "full.pdf"
    with matplotlib.rc_context(STYLE):  # the house style's TrueType fonts (pdf.fonttype 42)
        lean, _ = save_figure(fig, tmp_path / "lean")
        fig.savefig(full, format="pdf", metadata={"CreationDate": None})
    assert b"/FontFile2" in lean.read_bytes()
    drawn = _page_content(lean)
    assert drawn and drawn == _page_content(full)
    assert lean.stat().st_size < full.stat().st_size
    assert _backend_pdf_ps.get_glyphs_subset is not glyph_subset  # matplotlib's own, outside the block
    with lean_pdf_fonts():
        assert _backend_pdf_ps.get_glyphs_subset is glyph_subset


def test_where_the_lean_fonts_do_not_apply_matplotlib_writes_the_pdf(tmp_path: Path, monkeypatch) -> None:
    """A matplotlib whose subsetting takes other arguments (3.11: glyph indices) keeps its own."""

    def by_glyph_index(fontfile: str, glyphs: set[int]) -> None:
        raise AssertionError("not called in this test")

    monkeypatch.setattr(_backend_pdf_ps, "get_glyphs_subset", by_glyph_index)
    assert not lean_fonts_apply()
    with lean_pdf_fonts():
        assert _backend_pdf_ps.get_glyphs_subset is by_glyph_index
