## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {@var{def} =} brdf_blinnphong ()
## @deftypefnx {} {[@var{g}, @var{dg}] =} brdf_blinnphong (@var{X}, @var{q})
## The normalised Blinn-Phong lobe, defined here and nowhere else: with no
## argument its definition (see @code{model_def}); else the lobe of unit
## amplitude at @var{X} = [cos theta_i, cos theta_o, wi.wo] (both cosines
## > 0) for the shape parameters @var{q} = n, and its derivative by n:
## g = (n + 2) / (2 pi) cos^n theta_h (Ngan et al. 2005's normalisation:
## the lobe's projected integral over the half-vector hemisphere is 1).
## @end deftypefn

function [g, dg] = brdf_blinnphong (X, q)
  if (nargin == 0)
    g = struct ("type", "blinnphong", "title", "Blinn-Phong (normalised)",
                "shape", {{"n"}}, "lo", [0 1e-2], "hi", [Inf 1e7], "scale", {{"log"}},
                "starts", {{10 .^ (0:0.5:5)}},
                "width", @(q) 1 ./ sqrt (q(1) + 2),
                "formula", "ks (n+2)/(2 pi) cos(theta_h)^n",
                "glsl", ["    float g = (n + 2.0) / (2.0 * PI) * pow(ch, n);\n"]);
    return;
  endif
  G = brdf_geom (X);
  n = q(1);
  lc = log (G.ch);
  g = (n + 2) / (2 * pi) * exp (n * lc);
  if (nargout > 1)
    dg = g .* (1 / (n + 2) + lc);
  endif
endfunction
