## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{P} =} density_prep (@var{model}, @var{fname}, @var{table})
## The parts of an analytic model's sampling density that do not depend on
## the viewing direction (private, for @code{brdf_density},
## @code{brdf_sample} and @code{brdf_pdf}): the model checked, its type,
## the diffuse weight (the mean of rho_d over the channels) and one
## component per lobe and channel.  A Lafortune lobe keeps its Cxy, Cz and
## e (its axis and weight depend on wo: @code{density_mix}); a lobe of a
## physically based type becomes a GGX distribution of half vectors of
## roughness @code{def.width (q)} (exact for GGX, the type's own angular
## width for the others) weighted by ks times the albedo of its unit lobe
## at normal incidence (the model's check rejects negative rho_d, ks and
## e, so every weight is >= 0).  A tabulated density of MERL data
## (@code{density_table}; @var{table} true) is kept whole, with
## the weight of the cosine-weighted hemisphere beside it (@code{wd}, the
## defensive part that reaches every direction the table's cells miss).
## @end deftypefn
function P = density_prep (model, fname, table = false)
  if (table)
    P = struct ("model", model, "lafortune", false, "table", true, "wd", 0.1,
                "cxy", [], "cz", [], "e", [], "alpha", [], "wk", []);
    return;
  endif
  [model, def] = __lafortune_check_model__ (model, fname);
  P = struct ("model", model, "lafortune", isempty (def.lobe), "table", false,
              "wd", mean (model.rho_d), "cxy", [], "cz", [], "e", [], "alpha", [], "wk", []);
  if (P.lafortune)
    P.cxy = model.Cxy(:).';
    P.cz = model.Cz(:).';
    P.e = model.e(:).';
    return;
  endif
  nl = rows (model.ks);
  alpha = wk = zeros (1, 3 * nl);
  for c = 1:3
    p = __lafortune_model_pack__ (model, def, c);
    m = (numel (p) - 1) / nl;
    for k = 1:nl
      q = p(1 + (k - 1) * m + (1:m));
      j = k + (c - 1) * nl;
      alpha(j) = min (max (def.width (q(2:end)), 1e-4), 10);
      wk(j) = q(1) * model_albedo (def, [0; 1; q(2:end)], 0) / 3;
    endfor
  endfor
  wk(! isfinite (wk)) = 0;
  P.alpha = alpha;
  P.wk = max (wk, 0);
endfunction
