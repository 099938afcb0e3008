## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## study_scene_fits: which fit of a scene table looks best, over a folder of
## MERL materials -- the measurement behind lafortune_fit's defaults for a
## scene table (README, "Fits that look right").  For every MATERIAL.binary
## of DIR: the sphere scene (128 x 64 pixels, 8 samples per pixel), its
## scene table (merl_scene, 4 samples per pixel), fits of 1 to 3 lobes with
## each weighting and colour mode below, each rendered by rt_render with the
## measured render's samples and compared with it by img_compare (PSNR,
## FLIP, CIEDE2000, hue); the published 1-lobe fit (lafortune_ngan) where
## ../shared/data/ngan2005 has one.  One line per fit in OUT/MATERIAL.tsv
## (a material already there is not done again, so a stopped run goes on
## where it stopped), then the medians per fit and lobe count, and the
## materials where one more lobe raises FLIP by more than 0.002.  Not a
## test; about 1 to 2 minutes per material.
##
##   octave-cli --path inst --path src scripts/study_scene_fits.m DIR [OUT [MATERIAL ...]]

1;

function rows = study_material (file, fits, sc, ts, published)
  b = merl_read (file);
  [~, mat] = fileparts (file);
  ref = rt_render (sc, b, "progress", false);
  T = merl_scene (b, ts);
  rows = {};
  for i = 1:rows_of (fits)
    t0 = tic ();
    [~, info, ms] = brdf_fit (T, fits{i,2}, 3, fits{i,3}{:});
    t = toc (t0);
    alb = NaN;
    if (isfield (info, "albedo"))
      alb = max (info.albedo);
    endif
    for k = 1:3
      q = img_compare (ref, rt_render (sc, ms{k}, "progress", false));
      rows(end+1,:) = {mat, fits{i,1}, k, q.psnr, q.flip, q.deltae, q.hue, t, alb};
    endfor
  endfor
  if (exist (published, "file"))
    m = lafortune_ngan (published, mat);
    if (! isempty (m))
      q = img_compare (ref, rt_render (sc, m, "progress", false));
      rows(end+1,:) = {mat, "ngan2005 (published)", 1, q.psnr, q.flip, q.deltae, q.hue, 0, NaN};
    endif
  endif
endfunction

function n = rows_of (c)
  n = rows (c);
endfunction

warning ("off", "Octave:shadowed-function");
warning ("off", "lafortune:notConverged");
pkg load optim;
args = argv ();
models = any (strcmp (args, "--models"));
args = args(! strcmp (args, "--models"));
if (isempty (args))
  error ("study_scene_fits: give a folder of MERL .binary files");
endif
dir_ = args{1};
out = "study-scene-fits";
if (numel (args) > 1)
  out = args{2};
endif
if (! isfolder (out))
  mkdir (out);
endif
files = dir (fullfile (dir_, "*.binary"));
names = regexprep ({files.name}, '\.binary$', "");
if (numel (args) > 2)
  names = args(3:end);
endif
here = fileparts (mfilename ("fullpath"));
published = fullfile (here, "..", "..", "shared", "data", "ngan2005", "lafortune-1lobe.tsv");
## the fits compared: name, lafortune_fit options (a scene table's defaults
## are the recommended fit)
fits = {"relative, every family, separate (default)", "lafortune", {};
        "relative, every family, shared", "lafortune", {"color", "shared"};
        "relative, one family, separate", "lafortune", {"weight", "relative", "tries", 1};
        "image MSE (psnr), separate", "lafortune", {"weight", "psnr"};
        "image MSE (psnr), shared", "lafortune", {"weight", "psnr", "color", "shared"};
        "cube root, every family, separate", "lafortune", {"weight", "cuberoot"}};
if (models)
  ## --models: every model type, each with a scene table's defaults
  t = brdf_model ();
  fits = [t(:), t(:), repmat({{}}, numel (t), 1)];
endif
sc = scene_make ("sphere", "size", [128 64], "spp", 8);
ts = sc;
ts.spp = 4;
for i = 1:numel (names)
  f = fullfile (out, [names{i} ".tsv"]);
  if (exist (f, "file"))
    continue;
  endif
  printf ("study_scene_fits: %s (%d of %d)\n", names{i}, i, numel (names));
  fflush (stdout);
  R = study_material (fullfile (dir_, [names{i} ".binary"]), fits, sc, ts, published);
  txt = "";
  for r = 1:rows (R)
    txt = [txt sprintf("%s\t%s\t%d\t%.4f\t%.5f\t%.4f\t%.3f\t%.2f\t%.4f\n", R{r,:})];
  endfor
  __lafortune_write__ (f, "study_scene_fits", "text", txt);
endfor

## the medians
A = {};
for i = 1:numel (names)
  f = fullfile (out, [names{i} ".tsv"]);
  if (exist (f, "file"))
    c = textscan (fileread (f), "%s %s %f %f %f %f %f %f %f", "delimiter", "\t");
    A = [A; [c{1}, c{2}, num2cell([c{3:9}])]];
  endif
endfor
kinds = unique (A(:,2), "stable");
printf ("\n%d materials; medians over them (FLIP, CIEDE2000, hue in degrees, PSNR in dB), rt_render, sphere 128 x 64\n",
        numel (unique (A(:,1))));
printf ("%-44s | %-5s | %-7s %-6s %-6s %-7s | %s\n", "fit", "lobes", "FLIP", "dE", "hue", "PSNR",
        "FLIP up by > 0.002 with this lobe");
for i = 1:numel (kinds)
  for k = 1:3
    s = strcmp (A(:,2), kinds{i}) & [A{:,3}]' == k;
    if (! any (s))
      continue;
    endif
    v = cell2mat (A(s,4:7));
    up = {};
    if (k > 1)
      p = strcmp (A(:,2), kinds{i}) & [A{:,3}]' == k - 1;
      [~, a, b] = intersect (A(s,1), A(p,1));
      x = cell2mat (A(s,5)); y = cell2mat (A(p,5));
      mats = A(s,1);
      up = mats(a(x(a) > y(b) + 0.002));
    endif
    printf ("%-44s | %-5d | %-7.4f %-6.2f %-6.2f %-7.2f | %s\n", kinds{i}, k, median (v(:,2)),
            median (v(:,3)), median (v(:,4)), median (v(:,1)), strjoin (up(:)', ", "));
  endfor
endfor
