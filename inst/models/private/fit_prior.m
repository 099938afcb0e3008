## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## A scene table's prior (merl_scene's S.prior, a table of the material's
## whole hemisphere, and S.prior_weight = r): appended to the table with
## weights that sum to r times the table's own total weight in the fit's
## metric (for "psnr" the weights times the irradiance squared; prior rows
## get irradiance 1).  A single view (orthographic camera, directional
## light) fixes gamma = angle (L, V), where a lobe's base is
## Cxy cos gamma + (Cz - Cxy) uz vz: the scene's pixels determine only two
## combinations of a lobe's three parameters, and the prior the third.
function [S, n0] = fit_prior (S, weight)
  n0 = Inf;
  if (! isstruct (S) || ! isscalar (S) || ! isfield (S, "prior") || isempty (S.prior))
    return;
  endif
  P = S.prior;
  r = S.prior_weight;
  S = rmfield (S, {"prior", "prior_weight"});
  if (! (isstruct (P) && all (isfield (P, {"wi", "wo", "rgb"})) && isnumeric (r) && isscalar (r)
         && r >= 0 && isfinite (r)) || r == 0 || ! isfield (S, "weight"))
    if (r != 0)
      error ("lafortune:badSamples",
             "lafortune_fit: S.prior must be a table (wi, wo, rgb) and S.prior_weight a finite scalar >= 0");
    endif
    return;
  endif
  w = S.weight(:);
  if (strcmp (weight, "psnr"))
    w = mean (metric_spec ("psnr", S, "lafortune_fit").w, 2);   # weight .* irradiance^2
  endif
  n0 = rows (S.wi);
  wp = ones (rows (P.wi), 1);
  if (isfield (P, "weight"))
    wp = P.weight(:);
  endif
  wp *= r * sum (w) / max (sum (wp), realmin);
  S.wi = [S.wi; P.wi];
  S.wo = [S.wo; P.wo];
  S.rgb = [S.rgb; P.rgb];
  S.weight = [S.weight(:); wp];
  if (isfield (S, "irradiance"))
    S.irradiance = [S.irradiance; ones(rows (P.wi), columns (S.irradiance))];
  endif
endfunction
