## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_fit (@var{material})
## Step 2 of `make reproduce`: fit 1, 2 and 3 lobes per channel, the paper's
## way (in-plane table, grazing angles left out) and over the whole valid
## hemisphere; export every model (JSON, text table, BRDF Explorer) and write
## RESULTS/fit/MATERIAL.json with errors, times and the error-against-time
## traces.
## @end deftypefn
function repro_fit (material)
  c = repro_config ();
  warning ("off", "lafortune:notConverged");
  b = merl_read (fullfile (c.results, "data", [material ".binary"]));
  S.inplane = merl_plane (b, "max_angle", c.max_angle);
  S.hemisphere = merl_samples (b, "max_angle", c.max_angle, "max_samples", c.hemi_samples);
  outdir = fullfile (c.results, "fit");
  if (! isfolder (outdir))
    mkdir (outdir);
  endif
  R = struct ("material", material, "lobes", c.lobes);
  for method = {"inplane", "hemisphere"}
    mth = method{1};
    printf ("reproduce: [%s] fitting 1..%d lobes, %s (%d samples)\n", material,
            max (c.lobes), mth, rows (S.(mth).wi));
    fflush (stdout);
    [~, info, models] = lafortune_fit (S.(mth), max (c.lobes));
    r = struct ("samples", rows (S.(mth).wi), "time", info.time,
                "iterations", info.iterations, "converged", info.converged,
                "lobe_time", info.lobe_time);
    for k = c.lobes
      m = models{k};
      m.name = sprintf ("%s, %d lobe(s), %s fit", material, k, mth);
      base = fullfile (outdir, sprintf ("%s-%s-%d", material, mth, k));
      lafortune_export (m, [base ".json"], "json");
      lafortune_export (m, [base ".txt"], "text");
      lafortune_export (m, [base ".brdf"], "brdfexplorer");
      ## errors of this model on both tables
      for t = {"inplane", "hemisphere"}
        e = model_errors (m, S.(t{1}));
        r.errors.(t{1}).rmse(k,:) = e.rmse;
        r.errors.(t{1}).rel_rmse(k,:) = e.rel_rmse;
        r.errors.(t{1}).log_rmse(k,:) = e.log_rmse;
        r.errors.(t{1}).cos_rmse(k,:) = e.cos_rmse;
      endfor
      r.models{k} = rmfield (m, "name");
    endfor
    ## the error-against-time traces, thinned for the record
    for ch = 1:3
      T = info.trace{ch};
      keep = unique ([1:max(1, floor (rows (T) / 200)):rows(T), rows(T)]);
      r.trace{ch} = T(keep,:);
    endfor
    R.(mth) = r;
    printf ("reproduce: [%s] %s rmse (mean RGB) for %s lobes: %s; %.1f s\n", material, mth,
            mat2str (c.lobes), mat2str (mean (r.errors.(mth).rmse, 2)', 4), sum (info.time));
  endfor
  repro_save (fullfile (outdir, [material ".json"]), R);
endfunction

function e = model_errors (m, S)
  f = lafortune_eval (m, S.wi, S.wo);
  y = S.rgb;
  r = f - y;
  e.rmse = sqrt (mean (r .^ 2));
  e.rel_rmse = e.rmse ./ max (sqrt (mean (y .^ 2)), realmin);
  d = zeros (1, 3);
  for ch = 1:3
    yp = y(y(:,ch) > 0, ch);
    d(ch) = 0.01 * median (yp);
  endfor
  e.log_rmse = sqrt (mean ((log (max (f, 0) + d) - log (max (y, 0) + d)) .^ 2));
  e.cos_rmse = sqrt (mean ((r .* S.wi(:,3)) .^ 2));
endfunction
