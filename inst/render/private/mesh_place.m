## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{V}, @var{N}, @var{info}] =} mesh_place (@var{V}, @var{N}, @var{info}, @var{up}, @var{normalize})
## Put a mesh read from a file into the scene's y-up world (private, for
## scene_make).  @var{up} = @qcode{"z"} rotates the mesh by -90 degrees about
## x, (x, y, z) -> (x, z, -y): its z axis becomes the world's y and its -y
## side (the front in z-up tools) faces the camera on +z; @qcode{"y"} leaves
## it.  With @var{normalize} true the bounding box's centre goes to the
## origin and its largest side to 2.  Scene vertices are
## (@var{V} * rotation.' - center) * scale; @var{info} gets the fields up,
## rotation, center and scale.
## @end deftypefn
function [V, N, info] = mesh_place (V, N, info, up, normalize)
  R = eye (3);
  if (strcmpi (up, "z"))
    R = [1 0 0; 0 0 1; 0 -1 0];
  endif
  V = V * R.';
  if (! isempty (N))
    N = N * R.';
  endif
  c = [0 0 0];
  s = 1;
  if (normalize)
    lo = min (V, [], 1);
    hi = max (V, [], 1);
    c = (lo + hi) / 2;
    s = 2 / max (hi - lo);
    V = (V - c) * s;
  endif
  info.up = lower (up);
  info.rotation = R;
  info.center = c;
  info.scale = s;
endfunction
