## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## study_general: the general fit (lafortune_fit (merl_samples (B), n) with
## no options) against the other Lafortune fits, judged under held-out
## light, over a folder of MERL materials.  For every material, fits of 1
## to 3 lobes by each method:
##   general   the general fit of 40000 hemisphere samples (the weighting
##             kept and its selection scores are recorded);
##   log, cuberoot, plain, relative
##             the same samples without training views, one weighting alone
##             (the general fit's candidates, solid-angle weights, relative
##             errors);
##   log_cos, cuberoot_cos, relative_cos
##             the same with merl_samples' "cosine" measure (each bin's
##             weight times cos theta_i, as Ngan et al. 2005);
##   scene     the fit of the table of merl_scene on a 512 x 256 sphere,
##             4 samples per pixel, scene_make's default directional light;
##   oracle    the same, lit by the judge's light from behind (it has seen
##             that light: the bound a scene fit reaches there);
##   inplane   the paper's: the in-plane table of merl_plane;
##   ngan2005  the published 1-lobe fit (lafortune_ngan), where there is one.
## Each fit is rendered by rt_render on a 128 x 128 sphere, 2 samples per
## pixel, under three lights none of the other fits saw (the probes
## courtyard and forest, 64 light samples, and a directional light from
## behind and above, [0.2 1 -0.4]), from the measured render's cache, and
## compared with it by img_compare (FLIP, CIEDE2000, PSNR).  A render that
## is not finite gets FLIP NaN and a note.  Fit and judging times are
## recorded.
##
## Settings (environment variables):
##   MERL_DIR   folder of MATERIAL.binary files (required)
##   OUT        the results, JSON (default study-general.json in the current
##              folder); written after every material through a temporary
##              file and a rename.  A material already in OUT is not done
##              again, so a stopped run goes on where it stopped.
##   MATERIALS  space-separated subset of the materials (default: every
##              *.binary of MERL_DIR)
##   NGAN_TSV   the published fits (default
##              ../shared/data/ngan2005/lafortune-1lobe.tsv beside the
##              checkout; without it no ngan2005 fits are judged)
## At the end prints, as Markdown tables over the materials in OUT of this
## selection: median FLIP per method and lobe count, per light and for the
## mean over the lights (A); the general fit's targets against oracle,
## scene, ngan2005 and more lobes, beside log and cuberoot alone (B); the
## weighting the general fit kept (C); times per material (D).  JSON keeps
## NaN and Inf as null, and a row vector comes back from jsondecode as a
## column.  Not a test.
##
##   MERL_DIR=/path/to/merl octave-cli --path inst --path src scripts/study_general.m

1;

## one material: every fit, then the judging; R is the record kept in OUT
function R = study_material (file, name, ngan_file, lights)
  b = merl_read (file);
  R = struct ("name", name, "fits", [], "selection", [], "time_tables", [],
              "judge", [], "q", [], "notes", {{}});
  F = struct ("method", {}, "weight", {}, "time", {}, "models", {});
  tt = struct ();

  t0 = tic ();
  S = merl_samples (b, "max_samples", 40000);
  tt.hemisphere_views = toc (t0);
  t0 = tic ();
  [~, info, M] = lafortune_fit (S, 3);
  F(end+1) = fit_record ("general", info.weight, tt.hemisphere_views + toc (t0), M);
  R.selection = info.selection;
  R.selection.finite = isfinite (info.selection.flip);   # JSON keeps Inf as null
  clear S;
  report_fit (F(end), sprintf (", kept %s",
                               strjoin (arrayfun (@(c, k) sprintf ("%s (%d)", R.selection.weights{c}, k),
                                                  R.selection.chosen, R.selection.lobes,
                                                  "UniformOutput", false), ", ")));

  t0 = tic ();
  S0 = merl_samples (b, "max_samples", 40000, "views", false);
  tt.hemisphere = toc (t0);
  for w = {"log", "cuberoot", "plain", "relative"}
    t0 = tic ();
    [~, info, M] = lafortune_fit (S0, 3, "weight", w{1});
    F(end+1) = fit_record (w{1}, info.weight, toc (t0), M);
    report_fit (F(end), "");
  endfor
  clear S0;
  ## the same weightings times cos theta_i (merl_samples' "cosine" measure)
  S0 = merl_samples (b, "max_samples", 40000, "views", false, "measure", "cosine");
  for w = {"log", "cuberoot", "relative"}
    t0 = tic ();
    [~, info, M] = lafortune_fit (S0, 3, "weight", w{1});
    F(end+1) = fit_record ([w{1} "_cos"], info.weight, toc (t0), M);
    report_fit (F(end), "");
  endfor
  clear S0;

  scenes = {"scene", scene_make("sphere", "size", [512 256], "spp", 4);
            "oracle", scene_make("sphere", "size", [512 256], "spp", 4,
                                 "light_direction", [0.2 1 -0.4])};
  for s = 1:rows (scenes)
    t0 = tic ();
    T = merl_scene (b, scenes{s,2});
    tt.(scenes{s,1}) = toc (t0);
    t0 = tic ();
    [~, info, M] = lafortune_fit (T, 3);
    F(end+1) = fit_record (scenes{s,1}, info.weight, tt.(scenes{s,1}) + toc (t0), M);
    report_fit (F(end), "");
  endfor
  clear T;

  t0 = tic ();
  P = merl_plane (b);
  tt.plane = toc (t0);
  [~, info, M] = lafortune_fit (P, 3);
  F(end+1) = fit_record ("inplane", info.weight, toc (t0), M);
  report_fit (F(end), "");

  if (! isempty (ngan_file))
    m = lafortune_ngan (ngan_file, name);
    if (! isempty (m))
      F(end+1) = fit_record ("ngan2005", "published", 0, {m});
    endif
  endif
  R.fits = F;
  R.time_tables = tt;

  ## the judging: every fit from the measured render's cache
  Q = struct ("method", {}, "lobes", {}, "light", {}, "flip", {}, "deltae", {},
              "psnr", {}, "finite", {});
  J = struct ("light", {}, "time", {});
  for l = 1:numel (lights)
    t0 = tic ();
    [ref, ~, cache] = rt_render (lights(l).scene, b, "progress", false);
    if (! all (isfinite (ref(:))))
      R.notes{end+1} = sprintf ("%s: the measured render is not finite", lights(l).name);
    endif
    for f = 1:numel (F)
      for k = 1:numel (F(f).models)
        img = rt_render (lights(l).scene, F(f).models{k}, "progress", false, "cache", cache);
        ok = all (isfinite (img(:)));
        if (ok)
          q = img_compare (ref, img);
        else
          q = struct ("flip", NaN, "deltae", NaN, "psnr", NaN);
          R.notes{end+1} = sprintf ("%s, %s, %d lobes: render not finite (%d pixels)",
                                    lights(l).name, F(f).method, k,
                                    nnz (any (! isfinite (img), 3)));
          printf ("  note: %s\n", R.notes{end});
        endif
        Q(end+1) = struct ("method", F(f).method, "lobes", k, "light", lights(l).name,
                           "flip", q.flip, "deltae", q.deltae, "psnr", q.psnr, "finite", ok);
      endfor
    endfor
    J(end+1) = struct ("light", lights(l).name, "time", toc (t0));
    g = Q(strcmp ({Q.method}, "general") & strcmp ({Q.light}, lights(l).name));
    printf ("  judge %-9s %6.1f s; general FLIP %s\n", lights(l).name, J(end).time,
            sprintf ("%.4f ", [g.flip]));
    fflush (stdout);
  endfor
  R.judge = J;
  R.q = Q;
endfunction

## a fit's record: its models stripped to the parameters
function f = fit_record (method, weight, t, M)
  for k = 1:numel (M)
    M{k} = struct ("rho_d", M{k}.rho_d, "Cxy", M{k}.Cxy, "Cz", M{k}.Cz, "e", M{k}.e);
  endfor
  f = struct ("method", method, "weight", weight, "time", t, "models", {M});
endfunction

function report_fit (f, extra)
  printf ("  fit %-9s %6.1f s, weight %s%s\n", f.method, f.time, f.weight, extra);
  fflush (stdout);
endfunction

## a decoded JSON array of objects (struct array, cell, or one struct) as a cell
function c = as_cell (x)
  if (iscell (x))
    c = x(:)';
  elseif (isempty (x))
    c = {};
  else
    c = num2cell (x(:)');
  endif
endfunction

## X (materials x methods x lobes x lights) of FIELD from the records, NaN
## where a render failed; HAVE: the material has that fit
function [X, have] = collect (recs, methods, lights, field)
  X = NaN (numel (recs), numel (methods), 3, numel (lights));
  have = false (size (X));
  for i = 1:numel (recs)
    for r = as_cell (recs{i}.q)
      q = r{1};
      m = find (strcmp (methods, q.method));
      l = find (strcmp (lights, q.light));
      if (isempty (m) || isempty (l))
        continue;
      endif
      have(i,m,q.lobes,l) = true;
      if (! isempty (q.(field)))             # null: not finite
        X(i,m,q.lobes,l) = q.(field);
      endif
    endfor
  endfor
endfunction

## the median of x over the materials that have the fit (HAVE), with the
## failed renders (NaN) left out and counted; how many have it when not all
function s = med_str (x, have)
  bad = nnz (have & isnan (x));
  v = x(have & ! isnan (x));
  if (isempty (v))
    s = "-";
    return;
  endif
  s = sprintf ("%.4f", median (v));
  if (nnz (have) < numel (have))
    s = sprintf ("%s (%d materials)", s, nnz (have));
  endif
  if (bad)
    s = sprintf ("%s (%d NaN)", s, bad);
  endif
endfunction

## "x/y": on how many of the y materials with both (and HAVE) a < b
function s = count_str (a, b, have)
  ok = have & ! isnan (a) & ! isnan (b);
  s = sprintf ("%d/%d", nnz (ok & a < b), nnz (ok));
endfunction

## the largest rise of FLIP from k to k+1 lobes per material (F: materials x 3)
function r = rises (F)
  r = max (diff (F, 1, 2), [], 2);
endfunction

## the largest of the rises R and its material
function s = rise_str (r, mats)
  [v, i] = max (r);
  if (isempty (v) || isnan (v))
    s = "-";
  else
    s = sprintf ("%+.4f (%s)", v, mats{i});
  endif
endfunction

## "material v1 / v2, ..." for the materials MATS and their values
function s = list_str (mats, varargin)
  if (isempty (mats))
    s = "none";
    return;
  endif
  c = cell (1, numel (mats));
  for i = 1:numel (mats)
    v = cellfun (@(x) sprintf ("%.4f", x(i)), varargin, "UniformOutput", false);
    c{i} = sprintf ("%s %s", mats{i}, strjoin (v, " / "));
  endfor
  s = strjoin (c, ", ");
endfunction

## a record's notes as a cell (JSON keeps an empty list as [])
function c = notes_of (r)
  c = {};
  if (! isempty (r.notes))
    c = cellstr (r.notes)(:)';
  endif
endfunction

## the settings from the environment: the folder of MERL files, the
## results file, the materials, the published fits ("" when absent)
function [merl, out, names, ngan] = settings_of (here)
  merl = getenv ("MERL_DIR");
  if (isempty (merl) || ! isfolder (merl))
    error ("study_general: set MERL_DIR to a folder of MERL .binary files");
  endif
  out = getenv ("OUT");
  if (isempty (out))
    out = "study-general.json";
  endif
  names = strsplit (strtrim (getenv ("MATERIALS")));
  names = names(! cellfun (@isempty, names));
  if (isempty (names))
    files = dir (fullfile (merl, "*.binary"));
    names = regexprep ({files.name}, '\.binary$', "");
  endif
  if (isempty (names))
    error ("study_general: no *.binary files in %s", merl);
  endif
  for i = 1:numel (names)
    if (! exist (fullfile (merl, [names{i} ".binary"]), "file"))
      error ("study_general: no file %s.binary in %s", names{i}, merl);
    endif
  endfor
  ngan = getenv ("NGAN_TSV");
  if (isempty (ngan))
    ngan = fullfile (here, "..", "..", "shared", "data", "ngan2005", "lafortune-1lobe.tsv");
  endif
  if (! exist (ngan, "file"))
    printf ("study_general: no table of published fits (%s): no ngan2005 fits\n", ngan);
    ngan = "";
  endif
endfunction

## A: the median FLIP per method and lobe count, per light and for the
## mean over the lights
function print_medians (X, have, methods, lnames, n)
  nl = numel (lnames);
  printf ("\n## A. Median FLIP over %d materials (rt_render, sphere 128 x 128, 2 spp)\n", n);
  for l = 1:nl
    printf ("\n**%s**\n\n| method | 1 lobe | 2 lobes | 3 lobes |\n|---|---|---|---|\n", lnames{l});
    for m = 1:numel (methods)
      if (! any (have(:,m,:,l)(:)))
        continue;
      endif
      printf ("| %s |", methods{m});
      for k = 1:3
        printf (" %s |", med_str (X(:,m,k,l), have(:,m,k,l)));
      endfor
      printf ("\n");
    endfor
  endfor
endfunction

## B: the general fit's targets beside the hemisphere weightings alone,
## where it is not below the published fit, where FLIP rises with a lobe
function print_targets (X, have, methods, lnames, mats, n)
  nl = numel (lnames);
  mi = @(m) find (strcmp (methods, m));
  printf ("\n## B. Targets (general beside the hemisphere weightings alone)\n\n");
  cmp = {"general", "log", "cuberoot", "relative", "log_cos", "cuberoot_cos", "relative_cos"};
  printf ("| target | %s |\n|---|%s\n", strjoin (cmp, " | "), repmat ("---|", 1, numel (cmp)));
  lb = find (strcmp (lnames, "behind"));
  o3 = X(:,mi("oracle"),3,lb);
  row = @(label, f) printf ("| %s |%s\n", label,
                             sprintf (" %s |", cellfun (f, cmp, "UniformOutput", false){:}));
  row ("(i) behind, 3 lobes: median FLIP / oracle's median",
        @(c) sprintf ("%.3f", median (X(! isnan (X(:,mi(c),3,lb)),mi(c),3,lb))
                              / median (o3(! isnan (o3)))));
  row ("(i) behind, 3 lobes: median of FLIP / oracle's per material",
        @(c) sprintf ("%.3f", median ((X(:,mi(c),3,lb) ./ o3)(! isnan (X(:,mi(c),3,lb) ./ o3)))));
  for l = 1:nl
    for k = 1:3
      row (sprintf ("(ii) %s, %d lobe(s): FLIP below scene's", lnames{l}, k),
            @(c) count_str (X(:,mi(c),k,l), X(:,mi("scene"),k,l), have(:,mi(c),k,l)));
    endfor
  endfor
  for l = 1:nl
    row (sprintf ("(iii) %s, 1 lobe: FLIP below ngan2005's", lnames{l}),
          @(c) count_str (X(:,mi(c),1,l), X(:,mi("ngan2005"),1,l), have(:,mi("ngan2005"),1,l)));
  endfor
  for l = 1:nl
    row (sprintf ("(iv) %s: largest rise k -> k+1 (material)", lnames{l}),
          @(c) rise_str (rises (reshape (X(:,mi(c),:,l), n, 3)), mats));
    row (sprintf ("(iv) %s: materials rising > 0.002", lnames{l}),
          @(c) sprintf ("%d", nnz (rises (reshape (X(:,mi(c),:,l), n, 3)) > 0.002)));
  endfor

  printf ("\nWhere the 1-lobe FLIP is not below ngan2005's (general; FLIP general / ngan2005):\n\n");
  g = mi ("general");
  p = mi ("ngan2005");
  for l = 1:nl
    s = have(:,p,1,l) & ! (X(:,g,1,l) < X(:,p,1,l));
    printf ("- %s: %s\n", lnames{l}, list_str (mats(s), X(s,g,1,l), X(s,p,1,l)));
  endfor
  printf ("\nWhere FLIP rises by more than 0.002 with a lobe (material: largest rise):\n\n");
  for c = cmp
    for l = 1:nl
      r = rises (reshape (X(:,mi(c{1}),:,l), n, 3));
      s = r > 0.002;
      printf ("- %s, %s: %s\n", c{1}, lnames{l}, list_str (mats(s), r(s)));
    endfor
  endfor
endfunction

## C: the weighting the general fit kept, per material and lobe count
function print_kept (recs, mats, n)
  printf ("\n## C. The weighting the general fit kept (its lobe count before padding)\n\n");
  printf ("| material | 1 lobe | 2 lobes | 3 lobes | views FLIP, %s |\n|---|---|---|---|---|\n",
          "1-3 lobes per candidate");
  kept = cell (n, 3);
  for i = 1:n
    sel = recs{i}.selection;
    W = cellstr (sel.weights);
    for k = 1:3
      kept{i,k} = sprintf ("%s (%d)", W{sel.chosen(k)}, sel.lobes(k));
    endfor
    Fv = reshape (sel.flip, numel (W), []);
    printf ("| %s | %s | %s |\n", mats{i}, strjoin (kept(i,:), " | "),
            strjoin (cellfun (@(w, r) sprintf ("%s%s", w, sprintf (" %.4f", r)),
                              W(:)', num2cell (Fv, 2)', "UniformOutput", false), "; "));
  endfor
  printf ("\nCounts:\n\n");
  for k = 1:3
    [u, ~, j] = unique (kept(:,k));
    printf ("- %d lobe(s): %s\n", k, strjoin (cellfun (@(x, c) sprintf ("%s %d", x, c), u(:)',
                                                      num2cell (accumarray (j(:), 1))',
                                                      "UniformOutput", false), ", "));
  endfor
endfunction

## D: the times per material, of each fit and of each light's judging
function print_times (recs, mats, methods, light_names, n)
  printf ("\n## D. Time per material (s; a fit's time includes its own table; hemi: the table of log, cuberoot, plain)\n\n");
  fm = methods(1:end-1);
  printf ("| material |%s hemi |%s total |\n|---|%s\n", sprintf (" %s |", fm{:}),
          sprintf (" judge %s |", light_names{:}), repmat ("---|", 1, numel (fm) + numel (light_names) + 2));
  T = NaN (n, numel (fm) + 1 + numel (light_names));
  for i = 1:n
    F = as_cell (recs{i}.fits);
    for f = 1:numel (F)
      m = find (strcmp (fm, F{f}.method));
      if (! isempty (m))
        T(i,m) = F{f}.time;
      endif
    endfor
    T(i,numel (fm) + 1) = recs{i}.time_tables.hemisphere;
    J = as_cell (recs{i}.judge);
    for j = 1:numel (J)
      T(i,numel (fm) + 1 + find (strcmp (light_names, J{j}.light))) = J{j}.time;
    endfor
    printf ("| %s |%s %.0f |\n", mats{i}, sprintf (" %.1f |", T(i,:)), sum (T(i,:)));
  endfor
  if (n > 0)
    printf ("| median |%s %.0f |\n", sprintf (" %.1f |", median (T, 1)), median (sum (T, 2)));
  endif
endfunction

warning ("off", "Octave:shadowed-function");
warning ("off", "lafortune:notConverged");
warning ("error", "lafortune:noLightProbe");   # a missing probe is no judge
pkg load optim;
here = fileparts (mfilename ("fullpath"));
addpath (here);                                  # repro_save

[merl, out, names, ngan] = settings_of (here);

methods = {"general", "log", "cuberoot", "plain", "relative", "log_cos", "cuberoot_cos", "relative_cos", ...
           "scene", "oracle", "inplane", "ngan2005"};
judge = {{"light", "environment", "map", "courtyard", "light_samples", 64},
         {"light", "environment", "map", "forest", "light_samples", 64},
         {"light_direction", [0.2 1 -0.4]}};
lights = struct ("name", {"courtyard", "forest", "behind"}, "scene", []);
for l = 1:numel (lights)
  lights(l).scene = scene_make ("sphere", "size", [128 128], "spp", 2, judge{l}{:});
endfor
light_names = {lights.name};

recs = {};
if (exist (out, "file"))
  D = jsondecode (fileread (out));
  recs = as_cell (D.materials);
endif
done = cellfun (@(r) r.name, recs, "UniformOutput", false);
todo = names(! ismember (names, done));
printf ("study_general: %d materials, %d in %s, %d to do\n", numel (names),
        numel (names) - numel (todo), out, numel (todo));
for i = 1:numel (todo)
  printf ("study_general: %s (%d of %d)\n", todo{i}, i, numel (todo));
  fflush (stdout);
  t0 = tic ();
  recs{end+1} = study_material (fullfile (merl, [todo{i} ".binary"]), todo{i}, ngan, lights);
  repro_save (out, struct ("methods", {methods}, "lights", {light_names},
                           "materials", {recs}));
  printf ("study_general: %s done in %.1f s\n", todo{i}, toc (t0));
  fflush (stdout);
endfor

## the summary, over the selected materials in OUT
done = cellfun (@(r) r.name, recs, "UniformOutput", false);
recs = recs(ismember (done, names));
mats = cellfun (@(r) r.name, recs, "UniformOutput", false);
n = numel (recs);
[X, have] = collect (recs, methods, light_names, "flip");
## the mean over the lights: NaN when a light's render failed
X(:,:,:,end+1) = mean (X, 4);
have(:,:,:,end+1) = all (have, 4);
lnames = [light_names, {"mean"}];
nl = numel (lnames);
mi = @(m) find (strcmp (methods, m));

print_medians (X, have, methods, lnames, n);
print_targets (X, have, methods, lnames, mats, n);
print_kept (recs, mats, n);
print_times (recs, mats, methods, light_names, n);

notes = {};
for i = 1:n
  notes = [notes, cellfun(@(s) [mats{i} ": " s], notes_of (recs{i}), "UniformOutput", false)];
endfor
printf ("\nNotes: %s\n", merge (isempty (notes), "none", strjoin (notes, "; ")));
