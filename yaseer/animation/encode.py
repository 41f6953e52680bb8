"""Encoding painted frames: GIF, a self-contained HTML player, H.264 through ffmpeg, a PNG still."""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Sequence

from yaseer.animation.draw import Look, Painter, draw_moving, make_figure
from yaseer.animation.geometry import Frame
from yaseer.animation.scene import AnimationError, build_scene
from yaseer.run_arguments import ArgumentError, frame_size, frames_per_second
from yaseer.whole_files import staged

SUFFIXES = (".gif", ".mp4", ".html", ".png")


MAX_FRAMES = 360  # a longer run is shown by evenly spaced frames (its paths stay complete)


def frames_to_paint(count: int, max_frames: int = MAX_FRAMES) -> list[int]:
    """The frame numbers an animation shows: all, or ``max_frames`` evenly spaced ones (first and last kept)."""
    if max_frames < 2:
        raise AnimationError("An animation needs at least 2 frames")
    if count <= max_frames:
        return list(range(count))
    return sorted({round(k * (count - 1) / (max_frames - 1)) for k in range(max_frames)})


def render(frames: Sequence[Frame], out: Path, title: str = "", fps: float = 6.0,
           frame_number: int = 0, progress_file=None, max_frames: int = MAX_FRAMES, look: Look | None = None) -> int:
    """Write the animation to ``out`` (.gif, .mp4, .html; .png: only frame ``frame_number``).

    ``look`` (title, column names, unit, size; default: ``title`` at 1280 x 720)
    is how each frame looks (:mod:`.draw`).  Returns the number of frames
    written (at most ``max_frames``: a longer run is thinned evenly, see
    :func:`frames_to_paint`).  Raises :class:`AnimationError` for an unknown
    suffix, no frames, a missing frame, a bad size, or .mp4 without ffmpeg.  A
    progress bar (stderr) appears when painting takes over a second.
    """
    look = look or Look(title=title)
    suffix = out.suffix.lower()
    if suffix not in SUFFIXES:
        raise AnimationError(f"Unknown animation format {out.suffix!r}: use {', '.join(SUFFIXES)}")
    try:
        fps = frames_per_second(fps)
        frame_size(look.size)
    except ArgumentError as error:
        raise AnimationError(str(error)) from None
    scene = build_scene(frames)
    if suffix == ".png" and not 0 <= frame_number < len(scene.frames):
        count = len(scene.frames)
        raise AnimationError(f"Frame {frame_number} does not exist: the run has {count} frames, "
                             f"numbered from 0 to {count - 1}")
    if suffix == ".mp4" and ffmpeg_program() is None:
        raise AnimationError("Writing .mp4 needs ffmpeg, which is not installed here; use .gif or .html")
    with staged() as place:  # the file appears whole or not at all (Ctrl-C while painting or encoding)
        if suffix == ".png":
            Painter(scene, look).image(frame_number).save(place(out))
            return 1
        images = paint(frames, look, max_frames, progress_file, scene)
        if suffix == ".html":
            write_html(images, place(out), fps, look.title, out.stem)
        else:
            WRITERS[suffix](images, place(out), fps)
    return len(images)


def paint(frames: Sequence[Frame], look: Look, max_frames: int = MAX_FRAMES, progress_file=None,
          scene=None) -> list:
    """The frames an animation shows (see :func:`frames_to_paint`) as PIL images."""
    scene = scene or build_scene(frames)
    painter = Painter(scene, look)
    return _paint_all(painter, frames_to_paint(len(scene.frames), max_frames), progress_file)


def player(frames: Sequence[Frame], look: Look | None = None, fps: float = 6.0, max_frames: int = MAX_FRAMES,
           title: str = ""):
    """A matplotlib ``FuncAnimation`` of the frames (``.to_jshtml()`` for a notebook, ``.save()`` for a file).

    Its figure is a free-standing ``matplotlib.figure.Figure`` (not pyplot's), so
    a notebook does not also show it as a still.
    """
    from matplotlib.animation import FuncAnimation

    look = look or Look(title=title)
    scene = build_scene(frames)
    figure, ax = make_figure(scene, look)
    shown: list = []

    def update(number: int) -> list:
        for artist in shown:
            artist.remove()
        shown[:] = draw_moving(ax, scene, number, look)
        return shown

    return FuncAnimation(figure, update, frames=frames_to_paint(len(scene.frames), max_frames),
                         interval=1000.0 / fps, blit=False)


def _paint_all(painter: Painter, numbers: list[int], progress_file) -> list:
    from yaseer.progress import track

    return [painter.image(n) for n in track(numbers, description="rendering", unit="frame", file=progress_file)]


FAST_OCTREE = 2  # Image.Quantize.FASTOCTREE (a plain number for Pillow before 9.1)
GIF_COLOURS = 64  # line art in a few colours: plenty, and a quarter of the time of an adaptive 256


def write_gif(images: list, out: Path, fps: float) -> None:
    """An endlessly looping GIF, ``fps`` frames a second (Pillow; 64 colours, fast octree palette)."""
    frames = [image.quantize(colors=GIF_COLOURS, method=FAST_OCTREE) for image in images]
    frames[0].save(out, save_all=True, append_images=frames[1:], duration=round(1000.0 / fps), loop=0)


PLAYER = """<div class="yaseer-player" id="{id}" style="font-family: sans-serif; max-width: {width}px">
<div style="position: relative">
<img src="{background}" alt="{title}" style="width: 100%; height: auto; display: block">
<img class="yaseer-frame" src="{first}" alt="" style="position: absolute; left: 0; top: 0; width: 100%; height: auto">
</div>
<div style="display: flex; align-items: center; gap: 0.6em; margin-top: 0.3em">
<button type="button" style="min-width: 5em">pause</button>
<input type="range" min="0" max="{last}" value="0" style="flex: 1">
<span>frame <output>0</output> / {last}</span>
</div>
<script>
(function () {{
  const root = document.getElementById("{id}");
  const frames = {frames};
  const img = root.querySelector("img.yaseer-frame"), slider = root.querySelector("input");
  const number = root.querySelector("output"), play = root.querySelector("button");
  let current = 0, timer = null;
  function show(n) {{ current = n; img.src = frames[n]; slider.value = n; number.textContent = n;
                      root.dataset.frame = n; }}
  function start() {{ timer = setInterval(() => show((current + 1) % frames.length), {interval});
                      play.textContent = "pause"; }}
  function stop() {{ clearInterval(timer); timer = null; play.textContent = "play"; }}
  play.onclick = () => (timer ? stop() : start());
  slider.oninput = () => {{ stop(); show(Number(slider.value)); }};
  show(0);
  start();
}})();
</script>
</div>
"""

HTML_PAGE = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>{title}</title></head>
<body style="font-family: sans-serif">
{player}</body></html>
"""


PLAYER_COLOURS = 32  # line art, bold type and a few trace colours: what a frame's moving parts need
BACKGROUND_SAMPLES = 15  # frames the player's background is the median of


def player_layers(images: list) -> tuple:
    """(background, layers): what the frames mostly show, once, and per frame only the pixels that differ.

    The background is, pixel by pixel, the median of up to :data:`BACKGROUND_SAMPLES` frames
    spread over the run: the picture without the moving parts, where each part covers a
    pixel in few frames.  Each frame's layer is opaque where the frame differs from it and
    transparent elsewhere, in a palette of :data:`PLAYER_COLOURS` colours; a frame is its
    layer over the background.
    """
    import numpy as np
    from PIL import Image

    step = max(1, len(images) // BACKGROUND_SAMPLES)
    sample = np.stack([np.asarray(image.convert("RGB")) for image in images[::step]])
    background = np.median(sample, axis=0).astype(np.uint8)
    layers = []
    for image in images:
        frame = np.asarray(image.convert("RGB"))
        differs = (frame != background).any(axis=2)
        rgba = np.dstack([np.where(differs[..., None], frame, 0).astype(np.uint8), (differs * 255).astype(np.uint8)])
        layers.append(Image.fromarray(rgba, "RGBA").quantize(colors=PLAYER_COLOURS, method=FAST_OCTREE))
    return Image.fromarray(background, "RGB"), layers


def player_html(images: list, fps: float, title: str = "") -> str:
    """A self-contained player (one ``<div>``): the frames as PNG data, play/pause and a frame slider.

    The frames are layers over one background (:func:`player_layers`).  Several players
    may share a page (each keeps to its own ``<div>``); the ``data-frame`` attribute of
    the ``<div>`` is the frame shown.
    """
    import base64
    import html
    import io
    import json
    import uuid

    def url(image) -> str:
        buffer = io.BytesIO()
        image.save(buffer, format="PNG", optimize=True)
        return "data:image/png;base64," + base64.b64encode(buffer.getvalue()).decode("ascii")

    background, layers = player_layers(images)
    urls = [url(layer) for layer in layers]
    return PLAYER.format(id=f"yaseer-{uuid.uuid4().hex[:12]}", title=html.escape(title), first=urls[0],
                         background=url(background), last=len(urls) - 1, frames=json.dumps(urls),
                         interval=round(1000.0 / fps), width=images[0].size[0])


def write_html(images: list, out: Path, fps: float, title: str = "", name: str | None = None) -> None:
    """A self-contained page holding one :func:`player_html`; ``name`` titles a page without a title
    (default: ``out``'s stem)."""
    import html

    out.write_text(HTML_PAGE.format(title=html.escape(title or name or out.stem), player=player_html(images, fps, title)),
                   encoding="utf-8")


def html_player(frames: Sequence[Frame], look: Look | None = None, fps: float = 6.0,
                max_frames: int = MAX_FRAMES) -> str:
    """The frames painted and wrapped in a :func:`player_html` (for a notebook or a page)."""
    look = look or Look()
    return player_html(paint(frames, look, max_frames), fps, look.title)


def ffmpeg_program() -> str | None:
    """The ffmpeg to run: one on PATH, else the binary the imageio-ffmpeg wheel ships, else None."""
    found = shutil.which("ffmpeg")
    if found is not None:
        return found
    try:
        import imageio_ffmpeg
    except ImportError:
        return None
    try:
        return imageio_ffmpeg.get_ffmpeg_exe()
    except RuntimeError:  # the wheel has no binary for this platform
        return None


def write_mp4(images: list, out: Path, fps: float) -> None:
    """H.264 through the ffmpeg program: raw RGB frames piped to it."""
    import subprocess

    width, height = images[0].size
    width, height = width - width % 2, height - height % 2  # yuv420p wants even sizes
    command = [ffmpeg_program() or "ffmpeg", "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgb24",
               "-s", f"{width}x{height}", "-r", f"{fps}", "-i", "-", "-pix_fmt", "yuv420p", str(out)]
    data = b"".join(image.crop((0, 0, width, height)).tobytes() for image in images)
    result = subprocess.run(command, input=data, capture_output=True)
    if result.returncode != 0:
        raise AnimationError(f"ffmpeg failed: {result.stderr.decode(errors='replace').strip()[:200]}")


WRITERS = {".gif": write_gif, ".mp4": write_mp4}
