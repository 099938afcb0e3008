## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {@var{def} =} brdf_ggx ()
## @deftypefnx {} {[@var{g}, @var{dg}] =} brdf_ggx (@var{X}, @var{q})
## The GGX (Trowbridge-Reitz) lobe with height-correlated Smith masking and
## Schlick's Fresnel, defined here and nowhere else: with no argument its
## definition (see @code{model_def}); else the lobe of unit amplitude at
## @var{X} = [cos theta_i, cos theta_o, wi.wo] (both cosines > 0) for
## @var{q} = [alpha, F0], and its derivatives:
## g = D G2 F / (4 cos theta_i cos theta_o), D = alpha^2 / (pi cos^4
## theta_h (alpha^2 + tan^2 theta_h)^2), G2 = 1 / (1 + Lambda (theta_i) +
## Lambda (theta_o)), Lambda = (sqrt (1 + alpha^2 tan^2 theta) - 1) / 2.
## @end deftypefn

function [g, dg] = brdf_ggx (X, q)
  if (nargin == 0)
    g = struct ("type", "ggx", "title", "GGX (Trowbridge-Reitz, height-correlated Smith, Schlick)",
                "shape", {{"alpha", "F0"}}, "lo", [0 1e-4 0], "hi", [Inf 10 1],
                "scale", {{"log", "lin"}},
                "starts", {{10 .^ (-2.5:0.25:0), [1 0.05]}},
                "width", @(q) q(1),
                "formula", "ks D G2 F / (4 cos(theta_i) cos(theta_o)), D = alpha^2 / (pi ch^4 (alpha^2 + tan(theta_h)^2)^2), G2 = 1/(1 + Lambda_i + Lambda_o), Lambda = (sqrt(1 + alpha^2 tan(theta)^2) - 1)/2, F = F0 + (1-F0)(1-cd)^5",
                "glsl", ["    float a2 = alpha * alpha;\n" ...
                         "    float D = a2 / (PI * pow(ch, 4.0) * (a2 + t2) * (a2 + t2));\n" ...
                         "    float li = (sqrt(1.0 + a2 * (1.0 - ci * ci) / (ci * ci)) - 1.0) / 2.0;\n" ...
                         "    float lo = (sqrt(1.0 + a2 * (1.0 - co * co) / (co * co)) - 1.0) / 2.0;\n" ...
                         "    float g = D / (1.0 + li + lo) * (F0 + (1.0 - F0) * s5) / (4.0 * ci * co);\n"]);
    return;
  endif
  G = brdf_geom (X);
  a = q(1);
  F0 = q(2);
  a2 = a ^ 2;
  den = a2 + G.t2;
  D = a2 ./ (pi * G.ch .^ 4 .* den .^ 2);
  ti2 = (1 - G.ci .^ 2) ./ G.ci .^ 2;
  to2 = (1 - G.co .^ 2) ./ G.co .^ 2;
  ri = sqrt (1 + a2 * ti2);
  ro = sqrt (1 + a2 * to2);
  V = 1 ./ (1 + (ri - 1) / 2 + (ro - 1) / 2);
  DV = D .* V ./ (4 * G.ci .* G.co);
  g = DV .* (F0 + (1 - F0) * G.s5);
  if (nargout > 1)
    dlam = a * ti2 ./ (2 * ri) + a * to2 ./ (2 * ro);
    dg = [g .* (2 / a - 4 * a ./ den - V .* dlam), DV .* (1 - G.s5)];
  endif
endfunction
