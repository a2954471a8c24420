// The viewer's frame-time harness (docs/performance.md); never part of a
// shipped page. scripts/viewer_bench.sh (and the browser test) add it as a
// second script after viewer.js, whose top-level bindings (T, draw, setT,
// ...) it shares. #bench=K: K frames of playback at speed 1 and 60 frames a
// second from 40% of the schedule on, each drawn and laid out; the mean
// milliseconds per frame (script, style and layout; not paint) go to the
// page state as "bench". #bench=K&full: the same with every part and region
// recomputed each frame (the baseline without the per-interval movers).
'use strict';
function runBench(k, full) {
  quiet = true;
  const t0 = performance.now();
  const from = T0 + (TSTOP - T0) * 0.4;
  for (let i = 0; i < k; ++i) {
    if (full) curInterval = -1;
    T = Math.min(TSTOP, from + i * D / 60); exact = null; draw(); void document.body.offsetWidth;
  }
  quiet = false;
  extraState.bench = { full: full, frames: k, ms_per_frame: (performance.now() - t0) / k, parts: parts.length,
                       moving_parts: parts.filter(p => p.moves).length };
}
{
  const b = /[#&]bench=(\d+)/.exec(location.hash);
  if (b) {
    play(false);
    runBench(Number(b[1]), /full/.test(location.hash));
    setT(T0);
  }
}
