## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} repro_fit (@var{material})
## Fit step of `make reproduce` and `make database` (run by repro_step, which
## writes @var{R} to RESULTS/fit/MATERIAL.json): fit 1 to max(LOBES) lobes
## per channel to DATA_DIR/MATERIAL.binary with each method of METHODS,
## for each model type of MODELS (@code{brdf_fit}; a method without a model
## in its name fits the Lafortune model, @code{scene_ggx} GGX: see
## repro_method); the tables:
## @code{inplane}, the paper's way (plane of incidence, grazing angles left
## out), @code{hemisphere}, the whole valid hemisphere (subsampled to
## HEMI_SAMPLES, plain solid-angle weights), @code{general}, the recommended
## fit when the scene is not known (the same table with its training views:
## @code{lafortune_fit}'s defaults there, which choose the weighting by
## FLIP in those views; its record has @code{selection}), and
## @code{scene}, the fit for the scene's own light: the angle pairs the
## scene's pixels see, with @code{lafortune_fit}'s defaults for a scene
## table; a method may name its
## colour mode (@code{scene_shared}, see repro_table); export every model
## to RESULTS/fit/ MATERIAL-METHOD-K.json, .txt and .brdf (BRDF Explorer).
##
## @var{R}: @code{lobes}, and per method (@code{R.inplane},
## @code{R.hemisphere}, @code{R.scene_ggx}): @code{model} (the type),
## @code{samples}, @code{weight} and @code{color} (the
## fit's), @code{time}, @code{iterations},
## @code{converged}, @code{lobe_time} (K x 3), @code{errors.TABLE.rmse},
## @code{rel_rmse}, @code{log_rmse}, @code{cos_rmse} (K x 3, of each model
## on each method's table, TABLE a method of METHODS without its model;
## cos_rmse is weighted by cos theta_i as in Ngan et
## al. 2005; the models themselves are in their files, MATERIAL-METHOD-K.json),
## @code{parameters} (1 x K struct array: each model's parameters, the fields of
## its type, as in its file; the reports read them here),
## @code{params} (1 x K: the numbers a model holds, those of its type's
## fields, @code{brdf_model (type).fields}), @code{json_bytes} (1 x K: the
## size of its JSON file), for the types brdf_fit reports an albedo of
## @code{albedo} (K x 3: the largest directional albedo over the incidence
## angles brdf_fit checks, 0, 5, ..., 85 and 89 degrees; above 1 the fit
## reflects more light than it receives),
## and @code{trace} (1 x 3 cell, one per channel R, G, B: K x 2 arrays
## [seconds, rmse], the error of the best fit so far against run time, as
## brdf_fit's @code{info.trace}, thinned to about 200 rows; jsondecode reads
## them back as a cell, or as a 3 x K x 2 array when the K are equal).
## @end deftypefn
function R = repro_fit (material)
  c = repro_config ();
  warning ("off", "lafortune:notConverged");
  b = repro_merl (c, material);
  ## every method's table and fit options (an unknown name is an error
  ## there), each table made once (deterministic: the same as made again);
  ## the errors are reported on the tables of the methods without their
  ## models (ERR: their names)
  P = cellfun (@repro_method, c.methods);
  err = unique ({P.base}, "stable");
  S = struct ();
  for i = 1:numel (P)
    if (! isfield (S, P(i).table))
      S.(P(i).table) = repro_table (b, P(i).table, c, c.hemi_samples);
    endif
  endfor
  outdir = fileparts (repro_files ("model", c.results, material, "", 1));
  repro_mkdir (outdir);
  R = struct ("material", material, "lobes", c.lobes);
  fits = cell (0, 3);                   # every model: method, lobes, model
  for i = 1:numel (c.methods)
    mth = c.methods{i};
    p = P(i);
    def = brdf_model (p.model);           # an unknown type is an error here
    St = S.(p.table);
    printf ("reproduce: [%s] fitting 1..%d lobes, %s (%s, %d samples)\n", material,
            max (c.lobes), mth, def.title, rows (St.wi));
    fflush (stdout);
    [~, info, models] = brdf_fit (St, p.model, max (c.lobes), p.opts{:});
    r = struct ("model", p.model, "samples", rows (St.wi), "weight", info.weight, "color", info.color,
                "time", info.time, "iterations", info.iterations, "converged", info.converged,
                "lobe_time", info.lobe_time);
    if (isfield (info, "selection"))
      ## the general fit's choice: each candidate weighting's FLIP in the
      ## training views, and the weighting and lobe count kept per k
      s = info.selection;
      r.selection = struct ("weights", {s.weights}, "flip", s.flip, "chosen", {s.weights(s.chosen)},
                            "lobes", s.lobes, "views", s.views, "time", s.time);
    endif
    for k = c.lobes
      m = models{k};
      m.name = sprintf ("%s, %d lobe(s), %s fit", material, k, mth);
      base = repro_files ("model", c.results, material, mth, k);
      brdf_export (m, [base ".json"], "json");
      brdf_export (m, [base ".txt"], "text");
      brdf_export (m, [base ".brdf"], "brdfexplorer");
      ## its parameters, for the reports (which read them here, not from
      ## the files again)
      for f = def.fields
        r.parameters(k).(f{1}) = m.(f{1});
      endfor
      ## its size: the numbers of its type's fields, and its JSON file
      r.params(k) = sum (cellfun (@(f) numel (m.(f)), def.fields));
      r.json_bytes(k) = dir ([base ".json"]).bytes;
      fits(end+1,:) = {mth, k, m};
    endfor
    r.errors = struct ();                # filled below, for all models at once
    ## energy: brdf_fit reports the albedo of the physically based types'
    ## fits, for every lobe count
    if (isfield (info, "albedo_lobes"))
      for k = c.lobes
        r.albedo(k,:) = info.albedo_lobes(k,:);
      endfor
    endif
    ## the error-against-time traces, thinned for the record, in their one
    ## shape: per channel K x 2 [seconds, rmse], as brdf_fit gives them
    r.trace = cell (1, 3);
    for ch = 1:3
      T = info.trace{ch};
      r.trace{ch} = T(unique ([1:max(1, floor (rows (T) / 200)):rows(T), rows(T)]),:);
    endfor
    R.(mth) = r;
  endfor
  ## the errors of every model on every method's table, by brdf_error (the
  ## one place where the metrics are defined): a table's delta once, each
  ## model evaluated once per table
  for t = err
    [E, I] = brdf_error (fits(:,3), S.(repro_method (t{1}).table), {"plain", "log", "cosine"});
    for i = 1:rows (fits)
      [mth, k] = fits{i,1:2};
      R.(mth).errors.(t{1}).rmse(k,:) = E(i,:,1);
      R.(mth).errors.(t{1}).rel_rmse(k,:) = I(i,1).relative;
      R.(mth).errors.(t{1}).log_rmse(k,:) = E(i,:,2);
      R.(mth).errors.(t{1}).cos_rmse(k,:) = E(i,:,3);
    endfor
  endfor
  for i = 1:numel (c.methods)
    r = R.(c.methods{i});
    printf ("reproduce: [%s] %s rmse (mean RGB) for %s lobes: %s; %.1f s\n", material,
            c.methods{i}, mat2str (c.lobes), mat2str (mean (r.errors.(P(i).base).rmse, 2)', 4),
            sum (r.time));
  endfor
endfunction

