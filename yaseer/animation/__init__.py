"""Animating a listing's mechanism from the positions its programs computed.

One job per module, in the order of the flow:

- :mod:`.geometry`: points, bars, sliders, traced points, snapshots, frames;
- :mod:`.record`: the machine hook that records every ``GOSUB PROG n`` as a
  snapshot, one frame per printed line (:mod:`yaseer.recorded_run` runs a listing with it);
- :mod:`.scene`: what stays fixed over the run (bounds, traced paths, sizes);
- :mod:`.labels`: the joints' letters, as the paper names them;
- :mod:`.draw`: a frame drawn with matplotlib for a projector;
- :mod:`.encode`: GIF, HTML player, MP4, PNG still; :func:`player` for notebooks.

Importing this package imports no matplotlib or numpy.
"""

from yaseer.animation.draw import Look, Painter, draw_background, draw_frame, draw_moving
from yaseer.animation.encode import (
    MAX_FRAMES,
    SUFFIXES,
    WRITERS,
    ffmpeg_program,
    frames_to_paint,
    html_player,
    paint,
    player,
    player_html,
    render,
    write_gif,
    write_html,
    write_mp4,
)
from yaseer.animation.geometry import ORIGIN, Bar, Frame, Point, Slider, Snapshot, TracedPoint, distance, plus, polar
from yaseer.animation.record import Recorder, prepare_frame
from yaseer.animation.scene import AnimationError, Path2D, Scene, build_scene, path_segments, traced_paths

__all__ = [
    "AnimationError", "Bar", "Look", "Painter", "html_player", "paint", "player_html", "Frame", "MAX_FRAMES", "ORIGIN", "Path2D", "Point", "Recorder",
    "SUFFIXES", "Scene", "Slider", "Snapshot", "TracedPoint", "WRITERS", "build_scene", "distance",
    "draw_background", "draw_frame", "draw_moving", "ffmpeg_program", "frames_to_paint", "path_segments",
    "player", "plus", "polar", "prepare_frame", "render", "traced_paths",
    "write_gif", "write_html", "write_mp4",
]
