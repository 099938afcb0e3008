## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{G} =} fit_guard (@var{cosmin})
## @deftypefnx {} {@var{ok} =} fit_guard (@var{p}, @var{G}, @var{ymax})
## The acceptance test of a fitted channel (private).
##
## @code{G = fit_guard (cosmin)}: direction pairs that span the data's angular
## range (theta up to acos (@var{cosmin})), the in-plane pairs on a
## 0.5-degree grid, which reach the extremes of every lobe's base (ux vx + uy
## vy is largest in size in the plane); @code{G.x} = [a, c].
##
## @code{ok = fit_guard (p, G, ymax)}: false when the model @var{p} is not
## finite on G or exceeds 10 @var{ymax} there: a lobe that fits a few samples
## and explodes between them (or toward grazing angles).  The sum of the
## lobes' largest values on G (each base is linear in (a, c): two products
## per point) bounds the model; only when that bound fails is the model
## evaluated on all of G.
## @end deftypefn
function out = fit_guard (p, G, ymax)
  if (nargin == 1)
    amax = acosd (max (p, 0));
    t = linspace (0, amax, max (2, ceil (amax / 0.5) + 1));
    to = [-fliplr(t(2:end)), t];
    out.x = [reshape(sind (t(:)) * sind (to), [], 1), reshape(cosd (t(:)) * cosd (to), [], 1)];
    return;
  endif
  lim = 10 * max (ymax, realmin);
  bound = p(1) / pi;
  for k = 1:(numel (p) - 1) / 3
    bmax = max (p(3*k-1) * G.x(:,1) + p(3*k) * G.x(:,2));
    if (bmax > 0)
      bound += exp (min (p(3*k+1) * log (bmax), 300));
    endif
  endfor
  if (isfinite (bound) && bound <= lim)
    out = true;
    return;
  endif
  g = lafortune_core (p, G.x(:,1), G.x(:,2));
  out = all (isfinite (g)) && max (g) <= lim;
endfunction
