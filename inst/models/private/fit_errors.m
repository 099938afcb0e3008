## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## INFO's errors (brdf_error's values, metric_spec's finish) of the
## fit's model values F (N x 3, on the table of the specs REP, NAMES from
## fit_specs) and FK (a cell of the values of the fits with fewer lobes,
## for info.history; may be empty), channels not FITTED NaN; WEIGHT the
## fit's metric.  The one report of a fit's errors, for every model type.
function info = fit_errors (info, rep, names, F, Fk, fitted, weight)
  nlobes = rows (info.history);
  n = rows (F);
  ss0 = arrayfun (@(c) rep.plain.ss (zeros (n, 1), c), 1:3);
  ss = channel_ss (rep, names, F);
  hss = nan (nlobes, 3);
  hss(nlobes,:) = ss.plain;
  for k = 1:numel (Fk)
    hss(k,:) = channel_ss (rep, {"plain"}, Fk{k}).plain;
  endfor
  info = report_errors (info, rep, ss, ss0, hss, fitted, weight);
endfunction

## INFO's errors from the 1 x 3 sums of squares SS.(metric) of the fit, SS0
## (plain, of the zero model) and HSS (plain, per lobe count) with the specs
## REP; channels not FITTED get NaN
function info = report_errors (info, rep, ss, ss0, hss, fitted, weight)
  per = @(e) ifelse_nan (e, fitted);
  info.rmse = per (rep.plain.finish (ss.plain));
  rms0 = rep.plain.finish (ss0);
  info.rel_rmse = per (relative_error (info.rmse, rms0));
  info.log_rmse = per (rep.log.finish (ss.log));
  if (isfield (rep, "cosine"))
    info.cos_rmse = per (rep.cosine.finish (ss.cosine));
  endif
  if (strcmp (weight, "psnr"))
    info.error = rep.psnr.finish (ss.psnr);
  else
    info.error = per (rep.(weight).finish (ss.(weight)));
  endif
  for k = 1:rows (hss)
    info.history(k,:) = per (rep.plain.finish (hss(k,:)));
  endfor
endfunction

## The 1 x 3 sums of squares SS.(name) of the model values F (N x 3) for
## each metric of NAMES, with the specs REP
function ss = channel_ss (rep, names, F)
  for i = 1:numel (names)
    ss.(names{i}) = arrayfun (@(c) rep.(names{i}).ss (F(:,c), c), 1:3);
  endfor
endfunction

## E with NaN where FITTED is false (channels not fitted)
function e = ifelse_nan (e, fitted)
  e(! fitted) = NaN;
endfunction
