## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} study_bounded_judge (@var{before}, @var{after}, @var{merl_dir}, @var{out})
## The held-out FLIP of the fits that changed between two runs of
## study_bounded (files @var{before} and @var{after}), against the measured
## data of @var{merl_dir} (or the proxies of ../shared): a 256 x 128 sphere
## under three directional lights that no fit was made for (0.2,1,-0.4;
## 0.7,0.3,0.6; -0.6,0.5,-0.6), toned by the measured render's 99th
## percentile.  One row a fit and light in the tab-separated file @var{out}:
## the fit's key, the light, FLIP before (NaN when rt_render refuses the
## model) and after.  Directional light, one sample per pixel: the renders
## are deterministic, so the noise floor is 0.
## @end deftypefn
function study_bounded_judge (before, after, merl_dir, out)
  o = read_fits (before);
  n = read_fits (after);
  keys = fieldnames (n);
  ch = keys(cellfun (@(k) isfield (o, k) && ! strcmp (o.(k).v, n.(k).v), keys));
  L = {[0.2 1 -0.4], [0.7 0.3 0.6], [-0.6 0.5 -0.6]};
  proxy = fullfile (fileparts (mfilename ("fullpath")), "..", "..", "shared", "data", "merl-proxy");
  mats = unique (cellfun (@(k) n.(k).mat, ch, "uniformoutput", false));
  fid = fopen ([out ".tmp"], "w");
  for m = mats(:)'
    f = fullfile (merl_dir, [m{1} ".binary"]);
    if (! exist (f, "file"))
      f = fullfile (proxy, [m{1} ".binary"]);
    endif
    b = merl_read (f);
    mine = ch(cellfun (@(k) strcmp (n.(k).mat, m{1}), ch));
    for l = 1:numel (L)
      sc = scene_make ("sphere", "size", [128 256], "light_direction", L{l});
      ref = rt_render (sc, b, "progress", false);
      s = quantile (ref(:), 0.99);
      for c = mine(:)'
        fo = flip_of (sc, o.(c{1}).m, ref, s);
        fn = flip_of (sc, n.(c{1}).m, ref, s);
        fprintf (fid, "%s\t%d\t%.4f\t%.4f\n", c{1}, l, fo, fn);
      endfor
    endfor
    printf ("%s done\n", m{1}); fflush (stdout);
  endfor
  fclose (fid);
  rename ([out ".tmp"], out);
endfunction

function f = flip_of (sc, m, ref, s)
  try
    f = img_flip (min (ref / s, 1), min (rt_render (sc, m, "progress", false) / s, 1));
  catch err
    if (! strcmp (err.identifier, "lafortune:unboundedModel"))
      rethrow (err);
    endif
    f = NaN;
  end_try_catch
endfunction

## study_bounded's rows: the models by key (material, table, weight, lobes)
function d = read_fits (file)
  d = struct ();
  t = strsplit (strtrim (fileread (file)), "\n");
  for i = 1:numel (t)
    c = strsplit (t{i}, "\t", "collapsedelimiters", false);
    k = str2double (c{4});
    v = str2num (c{7});
    m = struct ("rho_d", v(1:3), "Cxy", reshape (v(4:3+3*k), k, 3),
                "Cz", reshape (v(4+3*k:3+6*k), k, 3), "e", reshape (v(4+6*k:3+9*k), k, 3));
    key = matlab.lang.makeValidName ([c{1} "_" c{2} "_" c{3} "_" c{4}]);
    d.(key) = struct ("mat", c{1}, "v", c{7}, "m", m);
  endfor
endfunction
