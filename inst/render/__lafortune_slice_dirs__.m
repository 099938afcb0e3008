## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{wi}, @var{wo}] =} __lafortune_slice_dirs__ (@var{ti}, @var{to}, @var{cg})
## Local directions of the pair with angles @var{ti} = angle (N, L),
## @var{to} = angle (N, V) and cos (angle (L, V)) = @var{cg} (column vectors
## or scalars): wo in the xz plane, wi at the azimuth phi with
## cos @var{cg} = cos ti cos to + sin ti sin to cos phi, cos phi clamped to
## [-1, 1] where no normal reaches the combination (the nearest reachable
## configuration).  Private: the one construction behind @code{scene_slice}
## and @code{merl_scene}.
## @end deftypefn
function [wi, wo] = __lafortune_slice_dirs__ (ti, to, cg)
  s = sin (ti) .* sin (to);
  cphi = (cg - cos (ti) .* cos (to)) ./ s;
  cphi(s <= 0) = 1;
  cphi = min (max (cphi, -1), 1);
  sphi = sqrt (1 - cphi .^ 2);
  wi = [sin(ti) .* cphi, sin(ti) .* sphi, cos(ti)];
  wo = [sin(to), zeros(size (to)), cos(to)];
  wi ./= sqrt (sum (wi .^ 2, 2));
endfunction
