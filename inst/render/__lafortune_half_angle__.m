## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{th} =} __lafortune_half_angle__ (@var{ti}, @var{to}, @var{gamma})
## The angle theta_h between a normal N and the half vector H = (L + V)/|L +
## V| (private), from ti = angle (N, L), to = angle (N, V) and gamma = angle
## (L, V) (radians, arrays that broadcast): N . L + N . V = N . (L + V) =
## |L + V| cos theta_h and |L + V| = 2 cos (gamma/2).  Where L and V are
## opposite (no half vector) theta_h is pi/2.  merl_scene (which pixels may
## hold the mirror direction) and pov_write_scene (the inner maps' angle)
## use it.
## @end deftypefn
function th = __lafortune_half_angle__ (ti, to, gamma)
  d = 2 * cos (gamma / 2);
  th = acos (min (max ((cos (ti) + cos (to)) ./ d, -1), 1));
  th(! (d > 1e-12) & true (size (th))) = pi / 2;
endfunction
