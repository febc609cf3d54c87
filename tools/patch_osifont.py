"""Make tmm's copy of osifont (tmm_cli/render/sheets/fonts/osifont.ttf) from the Debian one.

osifont 0.1.20220224 draws Э, э, Ё, ё as empty boxes. This script adds them: Э and э as the
mirror images of Є and є (the same strokes turned), Ё and ё as references to Ë and ë (the same
letters). Its «ь» is the capital «Ь» (ГОСТ 2.304 has a small letter): «ь» is made from «ы» without
its stroke «і» (the same small soft sign the font draws inside «ы»). Its «θ» is the script form «ϑ»
(so the sheets showed ϑ where the note writes θ): «θ» is made from «Θ» narrowed to 0,8 of its width
(a closed oval with its bar, as the note's θ). Nothing else changes; the
version string says so (GPL: modified files carry a notice). Running it again on its own output
changes nothing.

    python tools/patch_osifont.py /usr/share/fonts/truetype/osifont/osifont.ttf tmm_cli/render/sheets/fonts/osifont.ttf
"""

import sys

from fontTools.pens.recordingPen import DecomposingRecordingPen
from fontTools.pens.transformPen import TransformPen
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib import TTFont


def mirrored(font, src: str):
    """The glyph `src` mirrored left–right within its advance width (contours reversed)."""
    gs = font.getGlyphSet()
    adv, lsb = font["hmtx"][src]
    rec = DecomposingRecordingPen(gs)
    gs[src].draw(rec)
    pen = TTGlyphPen(gs)
    from fontTools.pens.reverseContourPen import ReverseContourPen

    rec.replay(ReverseContourPen(TransformPen(pen, (-1, 0, 0, 1, adv, 0))))
    return pen.glyph(), adv


def copied(font, src: str):
    gs = font.getGlyphSet()
    rec = DecomposingRecordingPen(gs)
    gs[src].draw(rec)
    pen = TTGlyphPen(gs)
    rec.replay(pen)
    return pen.glyph(), font["hmtx"][src][0]


def soft_sign(font):
    """«ь» as «ы» without its rightmost contour (the «і»), with the side bearing «ы» has on the right."""
    from fontTools.pens.recordingPen import RecordingPen

    gs = font.getGlyphSet()
    src = font.getBestCmap()[0x044B]
    rec = RecordingPen()
    gs[src].draw(rec)
    contours, cur = [], []
    for op, args in rec.value:
        cur.append((op, args))
        if op in ("closePath", "endPath"):
            contours.append(cur)
            cur = []
    xmax = [max(p[0] for _, a in c for p in a) for c in contours]
    keep = [c for c, x in zip(contours, xmax) if x < max(xmax)]  # drop the «і»
    pen = TTGlyphPen(gs)
    for c in keep:
        for op, args in c:
            getattr(pen, op)(*args)
    adv = font["hmtx"][src][0]
    rsb = adv - max(xmax)
    return pen.glyph(), int(round(max(x for x in xmax if x < max(xmax)) + rsb))


def narrowed(font, src: str, k: float = 0.8):
    """The glyph `src` scaled to `k` of its width (about its left side bearing), with its advance."""
    gs = font.getGlyphSet()
    adv, lsb = font["hmtx"][src]
    rec = DecomposingRecordingPen(gs)
    gs[src].draw(rec)
    pen = TTGlyphPen(gs)
    rec.replay(TransformPen(pen, (k, 0, 0, 1, lsb * (1 - k), 0)))
    return pen.glyph(), int(round(lsb + (adv - lsb) * k))


def main(src: str, dst: str) -> None:
    f = TTFont(src)
    cm = f.getBestCmap()
    if f["glyf"][cm[0x03D1]].isComposite():  # «ϑ» refers to «θ»: it keeps its own (script) strokes
        glyph, adv = copied(f, cm[0x03D1])
        glyph.recalcBounds(f["glyf"])
        f["glyf"][cm[0x03D1]] = glyph
        f["hmtx"][cm[0x03D1]] = (adv, glyph.xMin)
    for code, how, base in ((0x042D, mirrored, 0x0404), (0x044D, mirrored, 0x0454),
                            (0x0401, copied, 0x00CB), (0x0451, copied, 0x00EB), (0x03B8, narrowed, 0x0398)):
        name = cm[code]
        glyph, adv = how(f, cm[base])
        glyph.recalcBounds(f["glyf"])
        f["glyf"][name] = glyph
        f["hmtx"][name] = (adv, glyph.xMin if hasattr(glyph, "xMin") else 0)
    name = cm[0x044C]
    glyph, adv = soft_sign(f)
    glyph.recalcBounds(f["glyf"])
    f["glyf"][name] = glyph
    f["hmtx"][name] = (adv, glyph.xMin)
    for rec in f["name"].names:
        if rec.nameID == 5:
            text = rec.toUnicode().split("; tmm:")[0]
            rec.string = text + "; tmm: U+042D U+044D U+0401 U+0451 added, U+044C small, U+03B8 closed"
    f.save(dst)


if __name__ == "__main__":
    main(*sys.argv[1:3])
