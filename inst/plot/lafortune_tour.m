## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} lafortune_tour ()
## @deftypefnx {lafortune} {} lafortune_tour (@var{material})
## @deftypefnx {lafortune} {} lafortune_tour (@var{material}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {@var{r} =} lafortune_tour (@dots{})
## A walk through the toolbox for class, in well under a minute: read
## measured data, take the paper's in-plane table, fit 1, 2 and 3 lobes,
## plot data and fits, render a sphere with the data and with each fit, and
## compare the renders by PSNR and as a viewer sees them (FLIP, CIEDE2000,
## hue: @code{img_compare}).
##
## Each step prints the command it runs, so that it can be typed again, and
## what came out.  @var{material} is @qcode{"green-metallic-paint"}
## (default) or @qcode{"red-plastic"}, the toolbox's built-in stand-ins
## (@code{merl_standin}), or a MERL material struct (@code{merl_read}).
##
## Options:
## @table @code
## @item "folder"
## write the figures there as @file{tour-plane.png}, @file{tour-polar.png}
## and @file{tour-renders.png} (default: none; without a display the
## figures are then invisible).
## @item "size"
## the render's [height width] in pixels (default [128 64]).
## @item "spp"
## samples per pixel (default 8).
## @end table
##
## @var{r} holds what the tour made: @code{brdf}, @code{S}, @code{models},
## @code{info}, @code{scene}, @code{images} (measured render first),
## @code{psnr} (dB, one per fit), @code{flip}, @code{deltae}, @code{hue}
## (one per fit), @code{figures} (handles) and
## @code{files}.
##
## @example
## @group
## r = lafortune_tour ("red-plastic", "folder", tempdir ());
## r.psnr          # the 1-, 2-, 3-lobe renders against the measured one
## @end group
## @end example
## @seealso{merl_standin, merl_plane, lafortune_fit, plot_plane, plot_renders}
## @end deftypefn
function r = lafortune_tour (material = "green-metallic-paint", varargin)
  fname = "lafortune_tour";
  opt = __lafortune_parse_opts__ (varargin, fname, struct ("folder", "", "size", [128 64], "spp", 8));
  if (! isempty (opt.folder) && ! (ischar (opt.folder) && isfolder (opt.folder)))
    error ("lafortune:badOption", "%s: FOLDER must be an existing folder, got '%s'",
           fname, __lafortune_arg_str__ (opt.folder));
  endif
  t0 = tic ();
  step (1, "read the measured data");
  if (ischar (material))
    show (sprintf ("brdf = merl_standin (\"%s\");   %% or merl_read (\"%s.binary\")",
                   material, material));
    brdf = merl_standin (material);
  elseif (strcmp (__lafortune_material_kind__ (material), "merl"))
    show ("brdf = merl_read (file);");
    brdf = material;
  else
    error ("lafortune:badMaterial",
           "%s: MATERIAL must be a stand-in's name or a MERL material (merl_read), got %s",
           fname, class (material));
  endif
  printf ("  %s: %d of MERL's %d bins measured\n", brdf.name, nnz (brdf.valid), numel (brdf.valid));

  step (2, "the paper's table: the plane of incidence, grazing angles left out");
  show ("S = merl_plane (brdf);");
  S = merl_plane (brdf);
  printf ("  %d samples, theta_i 0 to %g degrees, theta_o -%g to %g\n", rows (S.wi),
          max (S.theta_i), max (S.theta_o), max (S.theta_o));

  step (3, "fit 1, 2 and 3 lobes per channel (Levenberg-Marquardt, leasqr)");
  show ("[m, info, models] = lafortune_fit (S, 3);");
  [~, info, models] = lafortune_fit (S, 3);
  printf ("  rmse (1/sr)   %9s %9s %9s\n", "R", "G", "B");
  for k = 1:3
    printf ("  %d lobe%s      %9.4f %9.4f %9.4f\n", k, ifelse (k > 1, "s", " "), info.history(k,:));
  endfor

  step (4, "plot the data and the fits at theta_i = 30 degrees (the paper's Fig. 2)");
  files = {};
  out = @(nm) ifelse (isempty (opt.folder), "", fullfile (opt.folder, nm));
  show ("plot_plane (brdf, models, \"theta_i\", 30);");
  figs(1) = plot_plane (brdf, models, "theta_i", 30, "file", out ("tour-plane.png"));
  show ("plot_polar ({brdf, models{3}});");
  figs(2) = plot_polar ({brdf, models{3}}, [15 30 45 60], "file", out ("tour-polar.png"));

  step (5, "render a sphere with the data and with each fit");
  show (sprintf ("scene = scene_make (\"sphere\", \"size\", %s, \"spp\", %d);",
                 mat2str (opt.size), opt.spp));
  scene = scene_make ("sphere", "size", opt.size, "spp", opt.spp);
  show ("ref = rt_render (scene, brdf);  img = rt_render (scene, models{k});");
  images = cell (1, 4);
  images{1} = rt_render (scene, brdf, "progress", false);
  for k = 1:3
    images{k+1} = rt_render (scene, models{k}, "progress", false);
  endfor

  step (6, "compare the renders with the measured data's: PSNR, and as a viewer sees them");
  show ("q = img_compare (ref, img)    # PSNR, FLIP, CIEDE2000 and hue difference");
  q = cellfun (@(x) img_compare (images{1}, x), images(2:end));
  psnr = [q.psnr];
  flip = [q.flip];
  deltae = [q.deltae];
  hue = [q.hue];
  printf ("  PSNR: %s dB for 1, 2, 3 lobes (higher is better)\n", strtrim (sprintf ("%.2f ", psnr)));
  printf ("  FLIP: %s   (0 = no visible difference, 1 = the most)\n", strtrim (sprintf ("%.3f ", flip)));
  printf ("  dE:   %s   (CIEDE2000, mean over the sphere: about 1 is just noticeable)\n",
          strtrim (sprintf ("%.2f ", deltae)));
  printf ("  hue:  %s   (degrees: how far the colours have turned)\n", strtrim (sprintf ("%.1f ", hue)));
  show ("plot_renders ({ref, img1, img2, img3}, {\"measured\", \"1 lobe\", \"2 lobes\", \"3 lobes\"}, psnr, \"map\", \"flip\");");
  figs(3) = plot_renders (images, {"measured", "1 lobe", "2 lobes", "3 lobes"}, psnr, "map", "flip",
                          "title", sprintf ("%s: sphere, rt_render", brdf.name),
                          "file", out ("tour-renders.png"));
  if (! isempty (opt.folder))
    files = cellfun (out, {"tour-plane.png", "tour-polar.png", "tour-renders.png"},
                     "uniformoutput", false);
    printf ("\n  figures: %s\n", strjoin (files, ", "));
  endif
  printf ("\nlafortune_tour: done in %.1f s\n", toc (t0));
  if (nargout > 0)
    r = struct ("brdf", brdf, "S", S, "models", {models}, "info", info, "scene", scene,
                "images", {images}, "psnr", psnr, "flip", flip, "deltae", deltae, "hue", hue,
                "figures", figs, "files", {files});
  endif
endfunction

function step (k, what)
  printf ("\n%d. %s\n", k, what);
  fflush (stdout);
endfunction

function show (cmd)
  printf ("  >> %s\n", cmd);
  fflush (stdout);
endfunction

%!demo
%! lafortune_tour ("green-metallic-paint");

%!test
%! d = tempname (); mkdir (d);
%! unwind_protect
%!   out = evalc ('r = lafortune_tour ("red-plastic", "folder", d, "size", [64 32], "spp", 2);');
%!   close (r.figures);
%!   assert (! isempty (strfind (out, ">> [m, info, models] = lafortune_fit (S, 3);")));
%!   assert (numel (r.models), 3);
%!   assert (size (r.psnr), [1 3]);
%!   assert (all (isfinite (r.psnr) & r.psnr > 10));
%!   assert (r.psnr(3) > r.psnr(1));         # 3 lobes render closer than 1
%!   assert (all (r.flip > 0 & r.flip < 1));
%!   assert (all (r.deltae >= 0 & isfinite (r.deltae)));
%!   assert (all (r.hue >= 0 & r.hue <= 180));
%!   assert (numel (r.files), 3);
%!   for k = 1:3
%!     s = dir (r.files{k});
%!     assert (s.bytes > 5000);
%!   endfor
%! unwind_protect_cleanup
%!   assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

%!error id=lafortune:badMaterial lafortune_tour (42)
%!error id=lafortune:badOption lafortune_tour ("red-plastic", "folder", "/nonexistent-folder")
%!error id=lafortune:badOption lafortune_tour ("red-plastic", "speed", 2)
