## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {@var{def} =} brdf_ashikhminshirley ()
## @deftypefnx {} {[@var{g}, @var{dg}] =} brdf_ashikhminshirley (@var{X}, @var{q})
## The isotropic Ashikhmin-Shirley specular lobe, defined here and nowhere
## else: with no argument its definition (see @code{model_def}); else the
## lobe of unit amplitude at @var{X} = [cos theta_i, cos theta_o, wi.wo]
## (both cosines > 0) for @var{q} = [n, F0], and its derivatives:
## g = (n + 1) / (8 pi) cos^n theta_h F / (cos theta_d max (cos theta_i,
## cos theta_o)), Schlick F = F0 + (1 - F0) (1 - cos theta_d)^5.  The
## models' diffuse term is Lambertian (rho_d / pi), not Ashikhmin and
## Shirley's coupled one.
## @end deftypefn

function [g, dg] = brdf_ashikhminshirley (X, q)
  if (nargin == 0)
    g = struct ("type", "ashikhminshirley", "title", "Ashikhmin-Shirley (isotropic)",
                "shape", {{"n", "F0"}}, "lo", [0 1e-2 0], "hi", [Inf 1e7 1],
                "scale", {{"log", "lin"}},
                "starts", {{10 .^ (0:0.5:5), [1 0.05]}},
                "width", @(q) 1 ./ sqrt (q(1) + 2),
                "formula", "ks (n+1)/(8 pi) cos(theta_h)^n F / (cd max(cos(theta_i), cos(theta_o))), F = F0 + (1-F0)(1-cd)^5",
                "glsl", ["    float g = (n + 1.0) / (8.0 * PI) * pow(ch, n) * (F0 + (1.0 - F0) * s5)\n" ...
                         "              / (cd * max(ci, co));\n"]);
    return;
  endif
  G = brdf_geom (X);
  n = q(1);
  F0 = q(2);
  lc = log (G.ch);
  A = (n + 1) / (8 * pi) * exp (n * lc) ./ (G.cd .* max (G.ci, G.co));
  g = A .* (F0 + (1 - F0) * G.s5);
  if (nargout > 1)
    dg = [g .* (1 / (n + 1) + lc), A .* (1 - G.s5)];
  endif
endfunction
