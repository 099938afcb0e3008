## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{cache} =} repro_trace (@var{scene})
## @deftypefnx {} {} repro_trace (@var{scene}, @var{cache})
## rt_render's trace of @var{scene} kept for the process: the measured
## render's trace (render_measured) serves the fits' renders (render_fits)
## when both steps run in one process (repro_material), so the scene is
## traced once.  With @var{cache}, keep it (the last one only); without,
## return the kept trace of that scene, or [] when there is none.  A render
## from the trace is bit for bit the one a full render gives (rt_render).
## @end deftypefn
function cache = repro_trace (scene, cache)
  persistent kept;
  if (nargin == 2)
    kept = cache;
    return;
  endif
  cache = [];
  if (! isempty (kept) && isequal (kept.key.scene, scene))
    cache = kept;
  endif
endfunction
