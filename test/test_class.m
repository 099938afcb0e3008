## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## Integration tests for class use: the README's "In class" block run as
## written, figures on a machine as a new user has it (a fresh HOME; Octave's
## default font missing), progress lines in logs, and one pair of directions
## above or below the horizon for every function that takes directions.

%!function code = readme_block ()
%!  top = getenv ("LAFORTUNE_TOP");
%!  if (isempty (top))
%!    top = fullfile (fileparts (mfilename ("fullpath")), "..");
%!  endif
%!  f = fullfile (top, "README.md");
%!  if (! isfile (f))                      # run from the test folder itself
%!    f = fullfile (pwd (), "README.md");
%!  endif
%!  txt = fileread (f);
%!  a = strfind (txt, "## In class");
%!  assert (numel (a) == 1, "README.md must have one '## In class' section");
%!  b = a + strfind (txt(a:end), "```octave")(1) + 9;
%!  e = b + strfind (txt(b:end), "```")(1) - 2;
%!  code = txt(b:e);
%!endfunction

%!function [st, out] = octave_run (code, env)
%!  ## a fresh octave-cli with the package's folder on the path
%!  d = fileparts (which ("__lafortune_write__"));   # the package root (PKG_ADD adds its folders)
%!  scr = [tempname() ".m"];
%!  fid = fopen (scr, "w");
%!  fprintf (fid, "addpath ('%s');\n%s\n", d, code);
%!  fclose (fid);
%!  [st, out] = system (sprintf ("%s octave-cli --no-gui --norc --no-history '%s' 2>&1", env, scr));
%!  unlink (scr);
%!endfunction

## the README's "In class" block, exactly as written, in a scratch folder
%!test
%! code = readme_block ();
%! assert (! isempty (strfind (code, "lafortune_fit (S, 3)")));
%! d = tempname (); mkdir (d);
%! old = cd (d);
%! before = get (0, "children");
%! unwind_protect
%!   if (! isempty (pkg ("list", "lafortune")))
%!     eval (code);                       # make check: the installed package
%!   else
%!     ## the package is on the path but not installed: all but "pkg load lafortune"
%!     printf ("note: lafortune is not installed; the block runs without its 'pkg load lafortune'\n");
%!     eval (strrep (code, "pkg load lafortune", ""));
%!   endif
%!   assert (isfile (fullfile (d, "gmp-2lobe.json")));
%!   assert (isfile (fullfile (d, "renders.png")));
%!   assert (size (imread (fullfile (d, "renders.png")), 3), 3);
%!   assert (numel (q), 3);
%!   assert (q(3).psnr > q(1).psnr);
%!   assert (q(3).flip < q(1).flip);          # 3 lobes look closer than 1
%!   assert (all ([q.deltae] >= 0 & [q.hue] >= 0));
%!   ## the general fit, judged in light no fit was made for
%!   assert (rows (G.Cxy), 2);
%!   assert (h(2) < h(1), mat2str (h, 3));
%! unwind_protect_cleanup
%!   cd (old);
%!   close (setdiff (get (0, "children"), before));
%!   assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

## a figure drawn by a new user: a fresh, empty HOME
%!test
%! h = tempname (); mkdir (h);
%! f = fullfile (h, "plane.png");
%! unwind_protect
%!   [st, out] = octave_run (sprintf (["m = struct ('rho_d', [0.2 0.1 0.1], 'Cxy', [-1 -1 -1], 'Cz', [1 1 1], 'e', [20 20 20]);\n" ...
%!                                     "close (plot_plane ([], m, 'file', '%s'));\n"], f),
%!                           sprintf ("HOME='%s'", h));
%!   assert (st == 0, "%s", out);
%!   img = imread (f);
%!   assert (columns (img) > 1000);
%!   assert (numel (unique (img(:))) > 20);
%! unwind_protect_cleanup
%!   assert (strncmp (h, tempdir (), numel (tempdir ())));
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (h, "s");
%! end_unwind_protect

## Octave's default font missing (as without fonts-freefont-otf, which
## octave-common only recommends): a clear error naming the package,
## not Octave's "unable to create graphics handle"
%!test
%! h = tempname (); mkdir (h);
%! unwind_protect
%!   [st, out] = octave_run (["m = struct ('rho_d', [0.2 0.1 0.1], 'Cxy', [-1 -1 -1], 'Cz', [1 1 1], 'e', [20 20 20]);\n" ...
%!                            "try\n plot_plane ([], m);\ncatch err\n disp (err.identifier); disp (err.message);\nend_try_catch\n"],
%!                           sprintf ("HOME='%s' OCTAVE_FONTS_DIR='%s'", h, h));
%!   assert (! isempty (strfind (out, "lafortune:noFonts")), out);
%!   assert (! isempty (strfind (out, "fonts-freefont-otf")), out);
%! unwind_protect_cleanup
%!   assert (strncmp (h, tempdir (), numel (tempdir ())));
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (h, "s");
%! end_unwind_protect

## progress lines: in a log (stdout not a terminal), whole lines, no
## carriage returns, one per 10% or 30 s; on a terminal, rewritten in place
%!test
%! d = fullfile (fileparts (which ("rt_render")), "private");
%! old = cd (d);
%! unwind_protect
%!   out = evalc (["p = progress_line ('work', 'log');\n" ...
%!                 "for f = 0.01:0.01:1, p = progress_line (p, f, 3 + 100 * f); endfor\n" ...
%!                 "progress_line (p, 'done', 103);\n"]);
%!   tty = evalc (["p = progress_line ('work', 'tty');\n" ...
%!                 "for f = 0.25:0.25:1, p = progress_line (p, f, 3 + 10 * f); endfor\n" ...
%!                 "progress_line (p, 'done', 13);\n"]);
%!   slow = evalc (["p = progress_line ('slow', 'log');\n" ...
%!                  "for f = 0.001:0.001:0.01, p = progress_line (p, f, 3 + 10000 * f); endfor\n"]);
%!   quick = evalc (["p = progress_line ('quick', 'log');\n" ...
%!                   "for f = 0.1:0.1:1, p = progress_line (p, f, f); endfor\n" ...
%!                   "progress_line (p, 'done', 1);\n"]);
%! unwind_protect_cleanup
%!   cd (old);
%! end_unwind_protect
%! assert (! any (out == "\r"));
%! L = strsplit (strtrim (out), "\n");
%! assert (numel (L), 11);                  # 1%, then each 10%, and the end
%! assert (L{end}, "work: 100% done in 103.0 s");
%! assert (! isempty (regexp (L{2}, "^work:  10% done, +\\d+ s left$", "once")));
%! assert (sum (tty == "\r"), 5);
%! assert (sum (tty == "\n"), 1);
%! ## under 10% but 30 s apart: a line every 30 s (at 3 s, 33 s, ...)
%! assert (numel (strsplit (strtrim (slow), "\n")), 4);
%! assert (isempty (quick));                # work under 2 s prints nothing

## rt_render's progress into a log file: no carriage returns
%!test
%! [st, out] = octave_run (["s = scene_make ('sphere', 'size', [240 240], 'spp', 32);\n" ...
%!                          "rt_render (s, merl_standin ('red-plastic'), 'mode', 'direct', 'chunk', 8192);\n"],
%!                         "");
%! assert (st == 0, "%s", out);
%! assert (! any (out == "\r"));
%! if (isempty (strfind (out, "rt_render: 100% done")))
%!   printf ("note: the render took under 2 s, so printed no progress\n");
%! else
%!   assert (numel (regexp (out, "rt_render: +\\d+% done, +\\d+ s left\n")) >= 1);
%! endif

## one pair of directions, above or below the horizon, for every function
## that takes directions (lafortune_core through lafortune_eval)
%!test
%! m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -0.9 -0.8], "Cz", [1 0.9 0.8], "e", [10 20 30]);
%! b = merl_synth (m);
%! up = [sin(0.5) 0 cos(0.5)]; mir = [-up(1:2) up(3)];
%! down = [0 sin(2) cos(2)];
%! for fn = {@lafortune_eval, @merl_eval, @material_eval}
%!   for mat = {m, b}
%!     if (isequal (fn{1}, @lafortune_eval) && isfield (mat{1}, "data")) continue; endif
%!     if (isequal (fn{1}, @merl_eval) && isfield (mat{1}, "Cxy")) continue; endif
%!     assert (fn{1} (mat{1}, [0 0 1], down), [0 0 0]);
%!     assert (fn{1} (mat{1}, down, [0 0 1]), [0 0 0]);
%!     assert (fn{1} (mat{1}, down, down), [0 0 0]);
%!     f = fn{1} (mat{1}, up, mir);
%!     assert (size (f), [1 3]);
%!     assert (f, m.rho_d / pi + [1 0.9^20 0.8^30], -0.05);
%!   endfor
%! endfor
%! [v, ok] = merl_eval (b, [0 0 1], down);
%! assert (v, [0 0 0]); assert (ok, false);
%! assert (merl_eval (b, up, mir, "linear"), m.rho_d / pi + [1 0.9^20 0.8^30], -0.05);
%! assert (merl_eval (b, [0 0 1], down, "linear"), [0 0 0]);

## scene_slice takes angles (radians): one pair above and one below the horizon
%!test
%! s = scene_make ("sphere");
%! m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -0.9 -0.8], "Cz", [1 0.9 0.8], "e", [10 20 30]);
%! b = merl_synth (m);
%! for mat = {m, b}
%!   up = scene_slice (s, mat{1}, 0.3, 0.4, "pairs");
%!   assert (size (up), [1 3]);
%!   assert (all (up > 0));
%!   assert (scene_slice (s, mat{1}, 2, 0.4, "pairs"), [0 0 0]);
%!   assert (scene_slice (s, mat{1}, 0.3, 2, "pairs"), [0 0 0]);
%!   assert (squeeze (scene_slice (s, mat{1}, 2, 2))', [0 0 0]);
%! endfor
%! assert (scene_slice (s, b, 0.3, 0.4, "pairs"), scene_slice (s, m, 0.3, 0.4, "pairs"), -0.05);
