## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{O}, @var{D}] =} __lafortune_camera_rays__ (@var{cam}, @var{x}, @var{y})
## Rays of the camera @var{cam} (from @code{scene_camera}) through the view
## points @var{x}, @var{y} (column vectors, in units of the view: -0.5 to 0.5
## from left to right and from bottom to top).  @var{O} and @var{D} are
## N x 3 origins and unit directions (private; the one ray generator of
## @code{rt_render}, @code{pov_cast} and @code{merl_scene}).
## @end deftypefn
function [O, D] = __lafortune_camera_rays__ (cam, x, y)
  x = x(:);
  y = y(:);
  if (strcmp (cam.type, "orthographic"))
    O = cam.eye + (x * cam.w) .* cam.r + (y * cam.h) .* cam.u;
    D = repmat (cam.f, numel (x), 1);
  else
    D = cam.f + (x * cam.w) .* cam.r + (y * cam.h) .* cam.u;
    D ./= sqrt (sum (D .^ 2, 2));
    O = repmat (cam.eye, numel (x), 1);
  endif
endfunction
