## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} plot_plane (@var{data}, @var{models})
## @deftypefnx {lafortune} {} plot_plane (@var{data}, @var{models}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{hf}, @var{hax}] =} plot_plane (@dots{})
## Plot in-plane BRDF data and fitted models at one incident angle, one
## panel per channel, as the paper's Fig. 2 and 3.
##
## @var{data} is a MERL material (@code{merl_read}, @code{merl_standin}),
## a table from @code{merl_plane} (its samples at the chosen incident angle
## are drawn), or empty.  @var{models} is a Lafortune model, a cell of
## models (drawn as lines, in order), or empty.  Each panel shows the BRDF
## (1/sr, log scale) against the outgoing angle theta_o in the plane of
## incidence (degrees; negative on the far side of the normal, where the
## mirror direction theta_o = -theta_i is marked by a dotted line).  The
## data are black dots, the models coloured lines named in the legend.
##
## Options:
## @table @code
## @item "theta_i"
## incident angle in degrees (default 30, as the paper's Fig. 2).
## @item "channels"
## which of R, G, B (1, 2, 3) to draw, one panel each (default 1:3).
## @item "names"
## legend names of the models (cellstr; default: each model's @code{name},
## else "K lobe(s)").
## @item "title"
## what the panels' titles start with (default: the data's name).
## @item "max_angle"
## largest |theta_o| drawn, degrees (default 80, the fits' range).
## @item "file"
## a PNG file to write the figure to (atomically).
## @end table
##
## @var{hf} is the figure, @var{hax} the panels' axes.  Without a display
## (octave-cli, the gnuplot toolkit) the figure is invisible: give a file.
##
## @example
## @group
## brdf = merl_standin ("green-metallic-paint");
## [m, info, models] = lafortune_fit (merl_plane (brdf), 2);
## hf = plot_plane (brdf, models, "theta_i", 30, "file", "fig2.png");
## @end group
## @end example
## @seealso{merl_plane, lafortune_fit, plot_polar, plot_slice}
## @end deftypefn
function [hf, hax] = plot_plane (data, models, varargin)
  fname = "plot_plane";
  if (nargin < 2)
    print_usage ();
  endif
  opt = __lafortune_parse_opts__ (varargin, fname, struct ("theta_i", 30, "channels", 1:3,
                                             "names", {{}}, "title", [],
                                             "max_angle", 80, "file", ""));
  ti = opt.theta_i;
  if (! (isnumeric (ti) && isscalar (ti) && ti >= 0 && ti < 90))
    error ("lafortune:badOption", "%s: THETA_I must be one angle in [0, 90) degrees", fname);
  endif
  ma = opt.max_angle;
  if (! (isnumeric (ma) && isscalar (ma) && ma > 0 && ma < 90))
    error ("lafortune:badOption", "%s: MAX_ANGLE must be a scalar in (0, 90) degrees", fname);
  endif
  chs = opt.channels;
  if (! (isnumeric (chs) && ! isempty (chs) && all (ismember (chs(:), 1:3))))
    error ("lafortune:badOption", "%s: CHANNELS must be a subset of 1:3 (R, G, B)", fname);
  endif
  [models, names] = plot_items (models, opt.names, fname, "MODELS");
  ## the data at theta_i
  to_d = rgb_d = [];
  dname = "";
  if (! isempty (data))
    if (isstruct (data) && isfield (data, "kind") && strcmp (data.kind, "plane"))
      k = abs (data.theta_i - ti) < 1e-9;
      if (! any (k))
        error ("lafortune:badOption",
               "%s: the table has no samples at THETA_I = %g degrees; it has %s",
               fname, ti, mat2str (unique (data.theta_i(:)).', 4));
      endif
      to_d = data.theta_o(k);
      rgb_d = data.rgb(k,:);
      dname = data.name;
    elseif (strcmp (__lafortune_material_kind__ (data), "merl"))
      S = merl_plane (data, "theta_i", ti, "max_angle", ma, "step", 0.5);
      to_d = S.theta_o;
      rgb_d = S.rgb;
      dname = S.name;
    else
      error ("lafortune:badMaterial",
             "%s: DATA must be a MERL material, a merl_plane table or empty, got %s",
             fname, class (data));
    endif
  endif
  ttl = opt.title;
  if (isempty (ttl))
    ttl = dname;
  endif
  if (! ischar (ttl))
    error ("lafortune:badOption", "%s: TITLE must be a string", fname);
  endif
  ## the models on a fine grid of theta_o in the plane of incidence
  to = (-ma:0.25:ma)';
  wi = repmat ([sind(ti) 0 cosd(ti)], numel (to), 1);
  wo = [sind(to) zeros(size (to)) cosd(to)];
  F = cell (1, numel (models));
  for j = 1:numel (models)
    F{j} = material_eval (models{j}, wi, wo);
  endfor

  chn = {"red", "green", "blue"};
  n = numel (chs);
  ## pixels: panels 320 x 290, room for labels left and below, titles above
  pw = 320; ph = 290; L = 75; G = 70; B = 55; T = 60;
  hf = plot_begin (fname, [L + n * pw + (n - 1) * G + 20, B + ph + T]);
  hax = zeros (1, n);
  co = get (0, "defaultaxescolororder");
  for p = 1:n
    ch = chs(p);
    hax(p) = plot_place (hf, [L + (p - 1) * (pw + G), B, pw, ph]);
    hl = [];
    lab = {};
    if (! isempty (to_d))
      y = rgb_d(:,ch);
      ok = y > 0;
      hl(end+1) = semilogy (hax(p), to_d(ok), y(ok), "k.", "markersize", 5);
      lab{end+1} = "data";
      hold (hax(p), "on");
    endif
    for j = 1:numel (models)
      y = F{j}(:,ch);
      y(y <= 0) = NaN;
      hl(end+1) = semilogy (hax(p), to, y, "linewidth", 1.5,
                            "color", co(mod (j - 1, rows (co)) + 1,:));
      lab{end+1} = names{j};
      hold (hax(p), "on");
    endfor
    ## the mirror direction
    yl = get (hax(p), "ylim");
    plot (hax(p), [-ti -ti], yl, ":", "color", [0.5 0.5 0.5]);
    text (hax(p), -ti, yl(2), " mirror", "verticalalignment", "top",
          "color", [0.4 0.4 0.4], "fontsize", 9);
    set (hax(p), "ylim", yl);
    hold (hax(p), "off");
    xlim (hax(p), [-ma ma]);
    set (hax(p), "xtick", -80:20:80);
    xlabel (hax(p), "theta_o (degrees)", "interpreter", "none");
    if (p == 1)
      ylabel (hax(p), "BRDF (1/sr)", "interpreter", "none");
    endif
    title (hax(p), sprintf ("%s channel", chn{ch}), "interpreter", "none");
    if (p == 1 && ! isempty (hl))
      legend (hax(p), hl, lab, "location", "northeast", "interpreter", "none");
    endif
  endfor
  head = sprintf ("in the plane of incidence, theta_i = %g degrees", ti);
  if (! isempty (ttl))
    head = [ttl ", " head];
  endif
  plot_heading (hf, head);
  plot_save (hf, opt.file, fname);
endfunction

%!demo
%! brdf = merl_standin ("green-metallic-paint");
%! [m, info, models] = lafortune_fit (merl_plane (brdf, "step", 2), 3);
%! plot_plane (brdf, models, "theta_i", 30);

%!shared d, b, m
%! d = tempname (); mkdir (d);
%! b = merl_standin ("red-plastic");
%! m = struct ("name", "2 lobes", "rho_d", [0.2 0.05 0.04], "Cxy", [-1 -1 -1; -0.5 -0.5 -0.5],
%!             "Cz", [1 1 1; 0.6 0.6 0.6], "e", [300 300 300; 10 10 10]);

%!test
%! f = fullfile (d, "plane.png");
%! [hf, hax] = plot_plane (b, {m}, "theta_i", 30, "file", f);
%! assert (numel (hax), 3);
%! assert (all (ishghandle (hax)));
%! close (hf);
%! info = imfinfo (f);
%! assert ([info.Width info.Height], [1195 405]);
%! img = imread (f);
%! assert (numel (unique (img(:))) > 20);     # not blank
%! assert (nnz (any (img != 255, 3)) > 0.05 * rows (img) * columns (img));

%!test
%! ## a merl_plane table, one channel, models only
%! S = merl_plane (b, "theta_i", [20 40], "step", 2);
%! hf = plot_plane (S, [], "theta_i", 40, "channels", 2);
%! close (hf);
%! hf = plot_plane ([], m, "channels", [1 3], "names", {"model"});
%! close (hf);

%!error <Invalid call> plot_plane (1)
%!error <no samples at THETA_I = 35> plot_plane (merl_plane (b, "theta_i", 30, "step", 5), [], "theta_i", 35)
%!error id=lafortune:badOption plot_plane (b, m, "theta_i", 95)
%!error id=lafortune:badOption plot_plane (b, m, "channels", 4)
%!error id=lafortune:badOption plot_plane (b, m, "names", {"a", "b"})
%!error id=lafortune:badMaterial plot_plane (b, {m, 3})
%!error id=lafortune:badMaterial plot_plane (42, m)
%!error id=lafortune:badFile plot_plane (b, m, "file", fullfile (tempdir (), "x.jpg"))

%!test
%! assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
