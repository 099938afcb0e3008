## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} plot_slice (@var{materials})
## @deftypefnx {lafortune} {} plot_slice (@var{materials}, @var{phi_d})
## @deftypefnx {lafortune} {} plot_slice (@dots{}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{hf}, @var{hax}] =} plot_slice (@dots{})
## The theta_h - theta_d image of a BRDF at one difference azimuth phi_d,
## the standard view of MERL data.
##
## @var{materials} is a MERL material, a Lafortune model or a cell of them
## (one panel each, all with the same colours).  @var{phi_d} is in degrees
## (default 90).  Each panel shows, in one channel, log10 of the BRDF (1/sr)
## at MERL's own grid: across, the half-vector angle theta_h on MERL's
## square-root scale (its bins are finer near the specular peak, theta_h =
## 0); up, the difference angle theta_d.  The colour bar under the panels
## gives the values (brighter values, at grazing theta_d > 80 degrees, saturate);
## grey marks missing (invalid) samples of measured data.
## A model is evaluated at the same grid points (phi_h = 0).
##
## Options:
## @table @code
## @item "channel"
## 1, 2 or 3 (R, G, B; default 2, green).
## @item "decades"
## range of the colours below the largest value, in decades (default 4).
## @item "names"
## the panels' titles (cellstr; default: the names of the materials).
## @item "file"
## a PNG file to write the figure to (atomically).
## @end table
##
## @example
## @group
## brdf = merl_standin ("green-metallic-paint");
## m = lafortune_fit (merl_plane (brdf), 2);
## plot_slice (@{brdf, m@}, 90, "names", @{"measured", "2-lobe fit"@});
## @end group
## @end example
## @seealso{merl_read, merl_eval, plot_plane, plot_polar}
## @end deftypefn
function [hf, hax] = plot_slice (materials, phi_d = 90, varargin)
  fname = "plot_slice";
  if (nargin < 1)
    print_usage ();
  endif
  opt = __lafortune_parse_opts__ (varargin, fname, struct ("channel", 2, "decades", 4,
                                             "names", {{}}, "file", ""));
  [items, names] = plot_items (materials, opt.names, fname, "MATERIALS");
  if (isempty (items))
    error ("lafortune:badMaterial", "%s: MATERIALS is empty; expected at least one material", fname);
  endif
  if (! (isnumeric (phi_d) && isscalar (phi_d) && phi_d >= 0 && phi_d < 180))
    error ("lafortune:badOption", "%s: PHI_D must be one angle in [0, 180) degrees", fname);
  endif
  ch = opt.channel;
  if (! (isscalar (ch) && any (ch == 1:3)))
    error ("lafortune:badOption", "%s: CHANNEL must be 1, 2 or 3 (R, G, B)", fname);
  endif
  dec = opt.decades;
  if (! (isnumeric (dec) && isscalar (dec) && dec > 0 && isfinite (dec)))
    error ("lafortune:badOption", "%s: DECADES must be a positive number", fname);
  endif
  ## MERL's index order: phi_d fastest (180), then theta_d (90), theta_h (90)
  ip = min (floor (phi_d + 1e-9), 179);
  rowsel = ip + 1 + 180 * (0:8099)';
  V = cell (1, numel (items));
  for i = 1:numel (items)
    m = items{i};
    if (strcmp (__lafortune_material_kind__ (m), "merl"))
      __lafortune_check_merl__ (m, fname);
      v = m.data(rowsel,ch);
      v(! m.valid(rowsel)) = NaN;
    else
      if (! exist ("wi", "var"))
        [wi, wo] = __lafortune_merl_grid__ ();
        wi = wi(rowsel,:);
        wo = wo(rowsel,:);
      endif
      v = material_eval (m, wi, wo)(:,ch);
    endif
    v(v <= 0) = 0;
    V{i} = log10 (reshape (v, 90, 90));      # rows theta_d, columns theta_h
  endfor
  ## the top of the colours: the largest value away from grazing angles
  ## (theta_d <= 80 degrees), where measurements are noisy; above it they saturate
  top = -Inf;
  for i = 1:numel (V)
    x = V{i}(1:81,:);
    x = x(isfinite (x));
    if (! isempty (x))
      top = max (top, max (x));
    endif
  endfor
  if (! isfinite (top))
    top = 0;
  endif
  lim = [top - dec, top];
  cmap = viridis (256);

  chn = {"red", "green", "blue"};
  n = numel (items);
  pw = 270; G = 60; L = 70; B = 150; T = 60;
  hf = plot_begin (fname, [L + n * pw + (n - 1) * G + 20, B + pw + T]);
  hax = zeros (1, n);
  th_ticks = [0 1 5 10 20 40 60 90];
  for i = 1:n
    hax(i) = plot_place (hf, [L + (i - 1) * (pw + G), B, pw, pw]);
    v = V{i};
    v(isinf (v)) = lim(1);                    # zero: the bottom of the scale
    image (hax(i), [0.5 89.5], [0.5 89.5], plot_rgb (v, cmap, lim));
    set (hax(i), "ydir", "normal", "xlim", [0 90], "ylim", [0 90], "tickdir", "out",
         "xtick", sqrt (th_ticks / 90) * 90, "xticklabel", arrayfun (@num2str, th_ticks, "uniformoutput", false),
         "ytick", 0:15:90);
    xlabel (hax(i), "theta_h (degrees, square-root scale)", "interpreter", "none");
    if (i == 1)
      ylabel (hax(i), "theta_d (degrees)", "interpreter", "none");
    endif
    title (hax(i), names{i}, "interpreter", "none");
  endfor
  ticks = ceil (lim(1)):floor (lim(2));
  w = min (n * pw + (n - 1) * G, 500);
  plot_cbar (hf, [L + (n * pw + (n - 1) * G - w) / 2, 66, w, 16], cmap, lim,
             sprintf ("BRDF (1/sr), %s channel, log scale; grey: no measurement", chn{ch}),
             ticks, arrayfun (@(k) sprintf ("1e%d", k), ticks, "uniformoutput", false));
  plot_heading (hf, sprintf ("theta_h - theta_d slice at phi_d = %g degrees", phi_d));
  plot_save (hf, opt.file, fname);
endfunction

%!demo
%! brdf = merl_standin ("green-metallic-paint");
%! m = lafortune_fit (merl_plane (brdf, "step", 2), 2);
%! plot_slice ({brdf, m}, 90, "names", {"measured (stand-in)", "2-lobe fit"});

%!shared d, b, m
%! d = tempname (); mkdir (d);
%! b = merl_standin ("red-plastic");
%! m = struct ("rho_d", [0.2 0.05 0.04], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [30 30 30]);

%!test
%! f = fullfile (d, "slice.png");
%! [hf, hax] = plot_slice ({b, m}, 90, "file", f);
%! assert (numel (hax), 2);
%! close (hf);
%! info = imfinfo (f);
%! assert ([info.Width info.Height], [690 480]);
%! img = imread (f);
%! assert (numel (unique (img(:))) > 50);     # not blank
%! assert (nnz (any (img != 255, 3)) > 0.2 * rows (img) * columns (img));

%!test
%! ## the MERL panel shows the table itself: bin (theta_h 0, theta_d 0, phi_d 90)
%! [hf, hax] = plot_slice (b, 90, "channel", 1, "decades", 3);
%! c = get (findobj (hax, "type", "image"), "cdata");
%! close (hf);
%! assert (size (c), [90 90 3]);

%!error <Invalid call> plot_slice ()
%!error id=lafortune:badMaterial plot_slice ({})
%!error id=lafortune:badOption plot_slice (m, 180)
%!error id=lafortune:badOption plot_slice (m, 90, "channel", 0)
%!error id=lafortune:badOption plot_slice (m, 90, "decades", -1)

%!test
%! assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
