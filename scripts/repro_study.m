## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} repro_study (@var{material})
## Study step of `make reproduce` (run by repro_step, which writes @var{R}
## to RESULTS/study/MATERIAL.json): which fit looks right.  Every table of
## STUDY_TABLES (@code{inplane}: the paper's plane of incidence;
## @code{hemisphere}: every valid bin with its solid-angle weight;
## @code{scene}: the angle pairs the scene's pixels see, @code{merl_scene},
## from STUDY_TABLE_SPP samples per pixel, with the whole hemisphere
## as a prior) is fitted with every weighting of STUDY_WEIGHTS, 1 to
## max (LOBES) lobes, and the scene table also with @code{image} weights
## (@code{lafortune_fit}'s "psnr": each pair's share of the image times its
## irradiance squared, the image's MSE, so the fit maximises the render's
## PSNR).  Each fit is rendered with POV-Ray in the scene and in a second
## scene lit from STUDY_LIGHT, and compared (PSNR and FLIP) with the measured data
## rendered there by POV-Ray with the same samples.  A model met before
## (another column, or the main fit step's) is rendered once, and a column
## that is a fit of the main step (same table, same weighting: the paper's
## in-plane/plain, the recommended scene/relative) takes its models instead of
## fitting again.
##
## @var{R}: @code{light_b} and @code{methods}, a struct array with
## @code{table}, @code{weight}, @code{psnr_a}, @code{psnr_b} (1 x LOBES:
## the scene, the second scene), @code{flip_a}, @code{flip_b} (HDR-FLIP,
## img_compare), @code{psnr_a_predicted} (from the scene
## table, @code{brdf_error} "psnr"), @code{fit_time} and @code{rmse}
## (mean RGB, on the method's own table).
## @end deftypefn
function R = repro_study (material)
  c = repro_config ();
  warning ("off", "lafortune:notConverged", "local");
  b = merl_read (repro_files ("merl", c.data_dir, material));
  sa = repro_scene (c);
  sb = sa;
  sb.light.direction = c.study_light(:)' / norm (c.study_light);
  ref_a = exrread ([repro_files("measured_pov", c.results, material) ".exr"]);
  printf ("reproduce: [%s] study: the measured data in the second scene (POV-Ray)\n", material);
  fflush (stdout);
  ref_b = pov_render (sb, b, "antialias", c.pov_aa, "threads", c.pov_threads);

  ## the tables
  T = struct ();
  for t = c.study_tables
    T.(t{1}) = repro_table (b, t{1}, c);
  endfor
  cols = {};
  for t = c.study_tables
    for w = c.study_weights
      cols(end+1,:) = {t{1}, w{1}};
    endfor
    if (strcmp (t{1}, "scene"))
      cols(end+1,:) = {"scene", "image"};
    endif
  endfor

  ## renders shared between columns: the main step's, and every model met;
  ## the main step's models by method
  nl = max (c.lobes);
  seen = {};
  done = zeros (0, 4);                # [PSNR A, PSNR B, FLIP A, FLIP B] per model
  main = struct ();
  F = jsondecode (fileread (repro_files ("render_fits", c.results, material)));
  Ff = jsondecode (fileread (repro_files ("fit", c.results, material)));
  for m = c.methods
    for k = 1:numel (c.lobes)
      f = [repro_files("model", c.results, material, m{1}, c.lobes(k)) ".json"];
      if (isfield (F, m{1}) && exist (f, "file"))
        seen{end+1} = brdf_import (f);
        done(end+1,:) = [F.(m{1})(k).psnr_pov, NaN, F.(m{1})(k).flip_pov, NaN];
        main.(m{1}){c.lobes(k)} = seen{end};
      endif
    endfor
  endfor

  M = struct ("table", {}, "weight", {}, "psnr_a", {}, "psnr_b", {}, "flip_a", {}, "flip_b", {},
              "psnr_a_predicted", {}, "fit_time", {}, "rmse", {});
  for i = 1:rows (cols)
    [tn, wn] = cols{i,:};
    S = T.(tn);
    w = wn;
    if (strcmp (wn, "image"))
      w = "psnr";                   # the image's MSE (lafortune_fit, "weight", "psnr")
    endif
    ## the main step's fit of this table with this weighting (the same table:
    ## its hemisphere is subsampled to HEMI_SAMPLES) is not made again
    same = (isfield (main, tn) && strcmp (w, Ff.(tn).weight) && strcmp (Ff.(tn).color, "separate")
            && isequal (c.lobes, 1:nl)
            && (! strcmp (tn, "hemisphere") || isinf (c.hemi_samples)));
    printf ("reproduce: [%s] study: %s table, %s weights, 1..%d lobes%s\n", material, tn, wn, nl,
            merge (same, " (the fit step's fits)", ""));
    fflush (stdout);
    if (same)
      models = main.(tn);
      fit_time = sum (Ff.(tn).time);
      rmse = mean (Ff.(tn).errors.(tn).rmse, 2)';
    else
      t0 = tic ();
      [~, info, models] = lafortune_fit (S, nl, "weight", w, "color", "separate");
      fit_time = toc (t0);
      rmse = mean (info.history, 2)';
    endif
    r = struct ("table", tn, "weight", wn, "psnr_a", nan (1, nl), "psnr_b", nan (1, nl),
                "flip_a", nan (1, nl), "flip_b", nan (1, nl),
                "psnr_a_predicted", nan (1, nl), "fit_time", fit_time, "rmse", rmse);
    for k = 1:nl
      m = models{k};
      j = find (cellfun (@(s) same_model (s, m), seen), 1);
      if (isempty (j))
        seen{end+1} = m;
        done(end+1,:) = NaN;
        j = numel (seen);
      endif
      if (isnan (done(j,1)))
        q = img_compare (ref_a, pov_render (sa, m, "antialias", c.pov_aa, "threads", c.pov_threads));
        done(j,[1 3]) = [q.psnr, q.flip];
      endif
      if (isnan (done(j,2)))
        q = img_compare (ref_b, pov_render (sb, m, "antialias", c.pov_aa, "threads", c.pov_threads));
        done(j,[2 4]) = [q.psnr, q.flip];
      endif
      r.psnr_a(k) = done(j,1);
      r.psnr_b(k) = done(j,2);
      r.flip_a(k) = done(j,3);
      r.flip_b(k) = done(j,4);
      if (isfield (T, "scene"))
        r.psnr_a_predicted(k) = brdf_error (m, T.scene, "psnr");
      endif
    endfor
    printf ("reproduce: [%s] study: %s/%s PSNR %s dB, FLIP %s (scene); %s dB, FLIP %s (second scene)\n",
            material, tn, wn, mat2str (r.psnr_a, 4), mat2str (r.flip_a, 3), mat2str (r.psnr_b, 4),
            mat2str (r.flip_b, 3));
    M(end+1) = r;
  endfor
  R = struct ("material", material, "light_b", sb.light.direction, "methods", M);
endfunction

## the same model: the same fields (the type too), every parameter the
## same to 1e-12 relative (the name aside): one render serves both
function tf = same_model (a, b)
  f = sort (setdiff (fieldnames (a), {"name"}));
  tf = isequal (f, sort (setdiff (fieldnames (b), {"name"})));
  for i = 1:numel (f)
    if (! tf)
      break;
    endif
    x = a.(f{i});
    y = b.(f{i});
    if (ischar (x) || ischar (y))
      tf = isequal (x, y);
    else
      tf = isequal (size (x), size (y)) && all (abs (x(:) - y(:)) <= 1e-12 * max (1, abs (x(:))));
    endif
  endfor
endfunction
