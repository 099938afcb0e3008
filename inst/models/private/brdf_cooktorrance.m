## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {@var{def} =} brdf_cooktorrance ()
## @deftypefnx {} {[@var{g}, @var{dg}] =} brdf_cooktorrance (@var{X}, @var{q})
## The Cook-Torrance lobe as Ngan et al. 2005 fit it, defined here and
## nowhere else: with no argument its definition (see @code{model_def});
## else the lobe of unit amplitude at @var{X} = [cos theta_i, cos theta_o,
## wi.wo] (both cosines > 0) for @var{q} = [m, F0], and its derivatives:
## g = D G F / (pi cos theta_i cos theta_o), Beckmann D = exp (-tan^2
## theta_h / m^2) / (m^2 cos^4 theta_h), V-groove G = min (1, 2 cos theta_h
## cos theta_o / (wo.h), 2 cos theta_h cos theta_i / (wo.h)), Schlick F =
## F0 + (1 - F0) (1 - cos theta_d)^5.
## @end deftypefn

function [g, dg] = brdf_cooktorrance (X, q)
  if (nargin == 0)
    g = struct ("type", "cooktorrance", "title", "Cook-Torrance (Beckmann, V-groove, Schlick)",
                "shape", {{"m", "F0"}}, "lo", [0 1e-4 0], "hi", [Inf 10 1],
                "scale", {{"log", "lin"}},
                "starts", {{10 .^ (-2.5:0.25:0), [1 0.05]}},
                "width", @(q) q(1),
                "formula", "ks D G F / (pi cos(theta_i) cos(theta_o)), D = exp(-tan(theta_h)^2/m^2) / (m^2 cos(theta_h)^4), G = min(1, 2 ch co/cd, 2 ch ci/cd), F = F0 + (1-F0)(1-cd)^5",
                "glsl", ["    float m2 = m * m;\n" ...
                         "    float D = exp(-t2 / m2) / (m2 * pow(ch, 4.0));\n" ...
                         "    float G = min(1.0, min(2.0 * ch * co / cd, 2.0 * ch * ci / cd));\n" ...
                         "    float g = D * G * (F0 + (1.0 - F0) * s5) / (PI * ci * co);\n"]);
    return;
  endif
  G = brdf_geom (X);
  m = q(1);
  F0 = q(2);
  D = exp (-G.t2 / m ^ 2) ./ (m ^ 2 * G.ch .^ 4);
  V = min (1, min (2 * G.ch .* G.co ./ G.cd, 2 * G.ch .* G.ci ./ G.cd));
  DG = D .* V ./ (pi * G.ci .* G.co);
  g = DG .* (F0 + (1 - F0) * G.s5);
  if (nargout > 1)
    dg = [g .* (2 * G.t2 / m ^ 3 - 2 / m), DG .* (1 - G.s5)];
  endif
endfunction
