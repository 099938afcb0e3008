## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} plot_polar (@var{materials})
## @deftypefnx {lafortune} {} plot_polar (@var{materials}, @var{theta_i})
## @deftypefnx {lafortune} {} plot_polar (@dots{}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{hf}, @var{hax}] =} plot_polar (@dots{})
## Polar plots of BRDFs in the plane of incidence, in the style of BRDF
## Explorer, for several incident angles.
##
## @var{materials} is a MERL material, a Lafortune model or a cell of them
## (measured data and fits side by side); each gets a panel, all with the
## same radial scale.  In a panel the surface is the horizontal line, the
## normal points up; for each incident angle in @var{theta_i} (degrees,
## default [15 30 45 60]) the light comes from the dashed line on the right,
## and the curve of that colour has, in each outgoing direction theta_o of
## the plane of incidence, a distance from the centre equal to the BRDF
## value there (1/sr; the grey half circles are labelled with it).
##
## Options:
## @table @code
## @item "channel"
## 1, 2 or 3 (R, G, B; default 2, green).
## @item "scale"
## @code{"linear"} (default: the radius is the BRDF) or @code{"log"} (the
## radius is log10 of the BRDF, over the top 3 decades).
## @item "names"
## the panels' titles (cellstr; default: the names of the materials).
## @item "max_angle"
## largest |theta_o| drawn, degrees (default 85).
## @item "file"
## a PNG file to write the figure to (atomically).
## @end table
##
## @example
## @group
## brdf = merl_standin ("red-plastic");
## m = lafortune_fit (merl_plane (brdf), 2);
## plot_polar (@{brdf, m@}, [20 40 60], "names", @{"measured", "2-lobe fit"@});
## @end group
## @end example
## @seealso{plot_plane, plot_slice, material_eval}
## @end deftypefn
function [hf, hax] = plot_polar (materials, theta_i = [15 30 45 60], varargin)
  fname = "plot_polar";
  if (nargin < 1)
    print_usage ();
  endif
  opt = __lafortune_parse_opts__ (varargin, fname, struct ("channel", 2, "scale", "linear",
                                             "names", {{}}, "max_angle", 85, "file", ""));
  [items, names] = plot_items (materials, opt.names, fname, "MATERIALS");
  if (isempty (items))
    error ("lafortune:badMaterial", "%s: MATERIALS is empty; expected at least one material", fname);
  endif
  ti = theta_i(:).';
  if (! (isnumeric (ti) && ! isempty (ti) && all (ti >= 0 & ti < 90)))
    error ("lafortune:badOption", "%s: THETA_I must be angles in [0, 90) degrees", fname);
  endif
  ch = opt.channel;
  if (! (isscalar (ch) && any (ch == 1:3)))
    error ("lafortune:badOption", "%s: CHANNEL must be 1, 2 or 3 (R, G, B)", fname);
  endif
  if (! ischar (opt.scale) || ! any (strcmp (opt.scale, {"linear", "log"})))
    error ("lafortune:badOption", "%s: SCALE must be \"linear\" or \"log\"", fname);
  endif
  ma = opt.max_angle;
  if (! (isnumeric (ma) && isscalar (ma) && ma > 0 && ma < 90))
    error ("lafortune:badOption", "%s: MAX_ANGLE must be a scalar in (0, 90) degrees", fname);
  endif
  ## BRDF values: outgoing angles in the plane, negative on the mirror side
  to = (-ma:0.5:ma)';
  wo = [sind(to) zeros(size (to)) cosd(to)];
  F = cell (numel (items), numel (ti));
  for i = 1:numel (items)
    for j = 1:numel (ti)
      wi = repmat ([sind(ti(j)) 0 cosd(ti(j))], numel (to), 1);
      f = material_eval (items{i}, wi, wo);
      F{i,j} = f(:,ch);
    endfor
  endfor
  fmax = max (cellfun (@max, F(:)));
  if (! (fmax > 0))
    fmax = 1;
  endif
  if (strcmp (opt.scale, "linear"))
    radius = @(f) max (f, 0);
    ## rings at round values, 3 to 5 of them
    st = 10 ^ floor (log10 (fmax / 4));
    st *= [1 2 2.5 5 10](find ([1 2 2.5 5 10] * st >= fmax / 5, 1));
    rings = st * (1:floor (fmax / st + 1e-9));
    R = max (fmax, rings(end));
    ring_lab = arrayfun (@(v) sprintf ("%.3g", v), rings, "uniformoutput", false);
  else
    lo = floor (log10 (fmax)) - 3;
    radius = @(f) max (log10 (max (f, realmin)) - lo, 0);
    R = log10 (fmax) - lo;
    rings = 1:floor (R);
    ring_lab = arrayfun (@(v) sprintf ("1e%d", v + lo), rings, "uniformoutput", false);
  endif

  chn = {"red", "green", "blue"};
  n = numel (items);
  pw = 330; ph = 190; G = 20; B = 45; T = 60; K = 150;
  hf = plot_begin (fname, [20 + n * (pw + G) + K, B + ph + T]);
  hax = zeros (1, n);
  co = get (0, "defaultaxescolororder");
  co = co(mod ((1:numel (ti)) - 1, rows (co)) + 1,:);
  t = linspace (0, pi, 91);
  for i = 1:n
    hax(i) = plot_place (hf, [20 + (i - 1) * (pw + G), B, pw, ph]);
    ha = hax(i);
    hold (ha, "on");
    for r = rings
      plot (ha, r * cos (t), r * sin (t), "-", "color", [0.85 0.85 0.85]);
    endfor
    plot (ha, [-1.05 1.05] * R, [0 0], "k-");
    plot (ha, [0 0], [0 1.05] * R, "-", "color", [0.7 0.7 0.7]);
    for k = 1:numel (rings)
      text (ha, rings(k), 0, ring_lab{k}, "verticalalignment", "top",
            "horizontalalignment", "center", "fontsize", 8, "color", [0.4 0.4 0.4]);
    endfor
    for j = 1:numel (ti)
      r = radius (F{i,j});
      plot (ha, r .* sind (to), r .* cosd (to), "-", "color", co(j,:), "linewidth", 1.5);
      plot (ha, [0 sind(ti(j))] * R, [0 cosd(ti(j))] * R, "--", "color", co(j,:));
    endfor
    hold (ha, "off");
    axis (ha, "equal");
    set (ha, "xlim", [-1.1 1.1] * R, "ylim", [-0.12 1.08] * R, "visible", "off");
    text (ha, 0, 1.08 * R, names{i}, "horizontalalignment", "center",
          "verticalalignment", "bottom", "fontweight", "bold", "interpreter", "none");
  endfor
  plot_key (hf, [20 + n * (pw + G), B + ph - 100, K, 100], co,
            arrayfun (@(a) sprintf ("theta_i = %g deg", a), ti, "uniformoutput", false));
  if (strcmp (opt.scale, "linear"))
    what = "the BRDF (1/sr)";
  else
    what = "log10 of the BRDF (1/sr), top 3 decades";
  endif
  plot_heading (hf, sprintf ("Plane of incidence, %s channel", chn{ch}));
  plot_heading (hf, sprintf ("radius in each outgoing direction: %s; dashed: the light's direction", what),
                B + ph + T - 22, false);
  plot_save (hf, opt.file, fname);
endfunction

%!demo
%! brdf = merl_standin ("red-plastic");
%! m = lafortune_fit (merl_plane (brdf, "step", 2), 2);
%! plot_polar ({brdf, m}, [20 40 60], "names", {"measured (stand-in)", "2-lobe fit"});

%!shared d, b, m
%! d = tempname (); mkdir (d);
%! b = merl_standin ("red-plastic");
%! m = struct ("rho_d", [0.2 0.05 0.04], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [30 30 30]);

%!test
%! f = fullfile (d, "polar.png");
%! [hf, hax] = plot_polar ({b, m}, [20 50], "file", f);
%! assert (numel (hax), 2);
%! close (hf);
%! info = imfinfo (f);
%! assert ([info.Width info.Height], [870 295]);
%! img = imread (f);
%! assert (numel (unique (img(:))) > 20);     # not blank
%! assert (nnz (any (img != 255, 3)) > 0.02 * rows (img) * columns (img));

%!test
%! hf = plot_polar (m, 30, "scale", "log", "channel", 1, "names", {"lobe"});
%! close (hf);

%!error <Invalid call> plot_polar ()
%!error id=lafortune:badMaterial plot_polar ({})
%!error id=lafortune:badMaterial plot_polar ("red-plastic")
%!error id=lafortune:badOption plot_polar (m, 90)
%!error id=lafortune:badOption plot_polar (m, 30, "channel", 4)
%!error id=lafortune:badOption plot_polar (m, 30, "scale", "dB")

%!test
%! assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
