"""The free room a sheet-1 figure leaves for its detail view, for the detail-view tests only: the figure's
shapes inside the drawing frame (inset), with the sheet's keep-outs and its Results block and pieces kept out,
as the renderer measures it before it places a detail view."""
from __future__ import annotations

from geomcon.render.free_area import FreeRoom
from geomcon.render.page import INSET, frame_box
from geomcon.render.svg import _keepouts, results_in_free_room


def results_and_room(fig, sl, page, scale, info, warnings, sol):
    """The sheet layout with its Results placed (in the figure's free room when the layout had none) and the
    :class:`FreeRoom` left around the figure, the keep-outs and those Results."""
    if not sl.info_here:
        sl = results_in_free_room(fig, sl, page, info, warnings, scale, sol.info_steps()) or sl
    outs = _keepouts(fig, sl, page, scale)
    if sl.info_here:
        x, y = sl.info_at
        outs.append((x - INSET, y, x + sl.info_w + INSET, y + sl.info_h + INSET))
        outs += [(pc.x - INSET, pc.y, pc.x + pc.w + INSET, pc.y + pc.h + INSET) for pc in sl.pieces]
    fx0, fy0, fx1, fy1 = frame_box(page.sheet)
    room = FreeRoom([s for g in fig.groups for s in g.shapes], (fx0 + INSET, fy0 + INSET, fx1 - INSET, fy1 - INSET),
                    outs)
    return sl, room
