## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{d}, @var{R}] =} env_dirs (@var{th}, @var{ph}, @var{rotation})
## The one reading of a lat-long map's angles (private, for
## @code{env_load}'s sky, @code{env_sample} and @code{scene_lights}):
## @var{th} from +y (row 1 of the map straight up), @var{ph} from -z (the
## map's centre column) toward +x, both columns of equal length; @var{d}
## (n x 3) the unit directions in the map's frame.  @var{R} is the map's
## turn of @var{rotation} degrees about +y (default 0), map frame to world:
## world directions are @var{d} @var{R}.'.
## @end deftypefn
function [d, R] = env_dirs (th, ph, rotation = 0)
  st = sin (th);
  d = [st .* sin(ph), cos(th), -st .* cos(ph)];
  a = rotation * pi / 180;
  R = [cos(a) 0 sin(a); 0 1 0; -sin(a) 0 cos(a)];
endfunction
