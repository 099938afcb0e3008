## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} study_bounded (@var{out}, @var{merl_dir}, @var{names})
## The fits of each MERL material of @var{merl_dir} (and the two proxies of
## ../shared when @var{names} is empty), one row a model in the
## tab-separated file @var{out}: material, table (inplane, hemisphere,
## general), weight, lobes, the model's bound on the whole hemisphere over
## the data's largest value (__lafortune_check_bounded__), the seconds of
## the fit, and the model's parameters (%.17g), so that two runs on two
## versions can be compared fit by fit.  The hemisphere table has at most
## 40000 samples.  Used for the before-and-after table of NEWS 0.12.0.
## @end deftypefn
function study_bounded (out, merl_dir, names)
  files = dir (fullfile (merl_dir, "*.binary"));
  paths = fullfile (merl_dir, {files.name});
  proxy = fullfile (fileparts (mfilename ("fullpath")), "..", "..", "shared", "data", "merl-proxy");
  paths = [paths, fullfile(proxy, {dir(fullfile (proxy, "*.binary")).name})];
  if (nargin > 2 && ! isempty (names))
    [~, nm] = cellfun (@fileparts, paths, "uniformoutput", false);
    paths = paths(ismember (nm, names));
  endif
  warning ("off", "lafortune:notConverged");
  tmp = [out ".tmp"];
  fid = fopen (tmp, "w");
  for i = 1:numel (paths)
    [~, name] = fileparts (paths{i});
    b = merl_read (paths{i});
    T = cell (3, 3);
    T(1,:) = {"inplane", merl_plane(b, "max_angle", 80), {""}};
    T(2,:) = {"hemisphere", merl_samples(b, "max_angle", 80, "max_samples", 40000, "views", false), ...
              {"plain", "cosine", "log"}};
    T(3,:) = {"general", merl_samples(b, "max_angle", 80), {""}};
    for t = 1:rows (T)
      for w = T{t,3}
        args = {};
        if (! isempty (w{1}))
          args = {"weight", w{1}};
        endif
        t0 = tic ();
        [~, ~, models] = lafortune_fit (T{t,2}, 3, args{:});
        sec = toc (t0);
        ymax = max (abs (T{t,2}.rgb), [], 1);
        for k = 1:3
          m = models{k};
          r = max (__lafortune_check_bounded__ (m) ./ ymax);
          v = [m.rho_d(:); m.Cxy(:); m.Cz(:); m.e(:)];
          fprintf (fid, "%s\t%s\t%s\t%d\t%.6g\t%.2f\t%s\n", name, T{t,1}, w{1}, k, r, sec,
                   sprintf ("%.17g ", v));
        endfor
      endfor
    endfor
    printf ("%s done\n", name); fflush (stdout);
  endfor
  fclose (fid);
  rename (tmp, out);
endfunction
