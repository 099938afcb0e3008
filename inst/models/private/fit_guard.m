## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{G} =} fit_guard (@var{cosmin})
## @deftypefnx {} {@var{G} =} fit_guard ("scene", @var{x}, @var{cg})
## @deftypefnx {} {@var{ok} =} fit_guard (@var{p}, @var{G}, @var{ymax})
## The acceptance test of a fitted channel (private).
##
## @code{G = fit_guard (cosmin)}: direction pairs that span the data's angular
## range (theta up to acos (@var{cosmin})), the in-plane pairs on a
## 0.5-degree grid, which reach the extremes of every lobe's base (ux vx + uy
## vy is largest in size in the plane); @code{G.x} = [a, c].
##
## @code{G = fit_guard ("scene", x, cg)}: for a scene table (rows x = [a, c],
## cos gamma = @var{cg} of each row, gamma the angle between light and
## viewer): every pair a normal can make at those gammas, ti and to on a
## grid up to 89.5 degrees with |ti - to| <= gamma <= ti + to (gamma
## itself on a grid over the table's range widened by 5 degrees), and the
## table's rows: what the scene's pixels can see, grazing angles and
## silhouettes included, where a table sampled at the pixels has gaps.  The
## margin in gamma rejects a lobe that is bounded only at the scene's exact
## gamma: with Cxy = Cz the base is Cxy (wi . wo) = Cxy cos gamma, a constant
## under an orthographic camera and a directional light, which a fit can
## use with a huge exponent and which explodes in any other view.
##
## @code{ok = fit_guard (p, G, ymax)}: false when the model @var{p} is not
## finite on G or exceeds 10 @var{ymax} there: a lobe that fits a few samples
## and explodes between them (or toward grazing angles).  The sum of the
## lobes' largest values on G (each base is linear in (a, c): two products
## per point) bounds the model; only when that bound fails is the model
## evaluated on all of G.
## @end deftypefn
function out = fit_guard (p, G, ymax)
  if (ischar (p))
    out.x = scene_set (G, ymax);
    return;
  endif
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
  g = __lafortune_lafortune_core__ (p, G.x(:,1), G.x(:,2));
  out = all (isfinite (g)) && max (g) <= lim;
endfunction

function X = scene_set (x, cg)
  ga = acos (min (max (cg, -1), 1));
  lo = max (min (ga) - 5 * pi / 180, 0);
  hi = min (max (ga) + 5 * pi / 180, pi);
  ng = max (1, min (25, ceil ((hi - lo) / (pi / 180)) + 1));
  gs = linspace (lo, hi, ng);
  step = 0.5 * (1 + (ng > 5));               # degrees: 0.5, or 1 with many gammas
  t = (0:step:89.5) * pi / 180;
  [TI, TO] = ndgrid (t, t);
  X = x;
  for g = gs
    ok = abs (TI(:) - TO(:)) <= g & g <= TI(:) + TO(:);
    [wi, wo] = __lafortune_slice_dirs__ (TI(ok), TO(ok), cos (g));
    X = [X; wi(:,1) .* wo(:,1) + wi(:,2) .* wo(:,2), wi(:,3) .* wo(:,3)];
  endfor
endfunction
