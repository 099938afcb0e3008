## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{ndefects} =} study_stability (@var{merl_dir})
## The stiff and extreme cases as a table (`make stability`): each case of
## stability_cases and, when @var{merl_dir} (or LAFORTUNE_STABILITY_MERL)
## holds them, the darkest and sharpest measured materials with 10%
## multiplicative noise and 1% outliers on their hemisphere table, through
## every fitter of stability_run.  Printed in Markdown: the case, per
## fitter what the toolbox does (the model's bound over the data's largest
## value on the whole hemisphere, or the error id), and the held-out FLIP
## of the growing fit against the truth (the model a synthetic table was
## made from, or the measured data) on a 192 x 96 sphere under a light
## from the side and behind, which no table was chosen for.  Directional
## light and one sample per pixel: the renders are deterministic, so the
## noise floor is 0.  Returns the number of defects (a non-finite or
## unbounded model, an error without an id); `make stability` fails on any.
## @end deftypefn
function nbad = study_stability (merl_dir = getenv ("LAFORTUNE_STABILITY_MERL"))
  C = stability_cases (1);
  measured = {"black-phenolic", "steel", "aluminium", "gray-plastic", "specular-black-phenolic"};
  for i = 1:numel (measured)
    f = fullfile (merl_dir, [measured{i} ".binary"]);
    if (! isempty (merl_dir) && exist (f, "file"))
      b = merl_read (f);
      S = merl_samples (b, "max_angle", 80, "max_samples", 20000, "views", false);
      randn ("seed", i); rand ("seed", i);
      S.rgb .*= max (1 + 0.1 * randn (size (S.rgb)), 0);
      o = rand (rows (S.rgb), 1) < 0.01;
      S.rgb(o,:) *= 100;
      C(end+1) = struct ("name", [measured{i} ", noise and outliers"], "S", S, "truth", b);
    endif
  endfor
  if (numel (C) == numel (stability_cases (1)))
    printf ("(no measured materials: set LAFORTUNE_STABILITY_MERL to a folder of MERL files)\n\n");
  endif
  F = stability_run ();
  scene = scene_make ("sphere", "size", [96 192], "light_direction", [0.6 0.5 -0.6]);
  printf ("| case | %s | held-out FLIP (grow) |\n|---|%s---|\n", strjoin (F, " | "),
          repmat ("---|", 1, numel (F)));
  nbad = 0;
  for i = 1:numel (C)
    cells = cell (1, numel (F));
    grow = [];
    for j = 1:numel (F)
      r = stability_run (C(i).S, F{j});
      switch (r.what)
        case "bounded"
          cells{j} = sprintf ("bound %.3g", r.ratio);
        case "error"
          cells{j} = strrep (r.id, "lafortune:", "");
        otherwise
          cells{j} = ["**" r.what "**"];
          nbad += 1;
      endswitch
      if (strcmp (F{j}, "grow") && strcmp (r.what, "bounded"))
        grow = r.model;
      endif
    endfor
    flip = "-";
    if (! isempty (grow) && ! isempty (C(i).truth))
      ref = rt_render (scene, C(i).truth, "progress", false);
      img = rt_render (scene, grow, "progress", false);
      s = max (ref(:));
      if (s > 0)
        flip = sprintf ("%.3f", img_flip (ref / s, img / s));
      endif
    endif
    printf ("| %s | %s | %s |\n", C(i).name, strjoin (cells, " | "), flip);
    fflush (stdout);
  endfor
  printf ("\nbound: the model's largest value on the whole hemisphere over the data's (at most 10);\n");
  printf ("an error id: the table refused, nothing returned.  %d defects.\n", nbad);
endfunction
