## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} db_sheet (@var{material})
## Gallery step of `make database` (run by repro_step, which writes @var{R}
## to RESULTS/sheet/MATERIAL.json): the material's contact sheet
## RESULTS/sheet/MATERIAL.png, one row per fit method (in-plane: the
## paper's, hemisphere, scene: the recommended), the measured data rendered
## by POV-Ray (the reference of the fits' PSNR) first and then the render
## of each lobe count, titled "METHOD K: PSNR, FLIP, dE" (the POV-Ray
## render's PSNR, HDR-FLIP and mean CIEDE2000 against the measured one, as
## in the record of repro_render_fits), all at the measured render's
## exposure; in make database a last row has the published fit
## (repro_render_fits's ngan2005) when it was rendered.  @var{R}: @code{file} (the PNG's name, relative to RESULTS)
## and @code{exposure} (stops).
## @end deftypefn
function R = db_sheet (material)
  c = repro_config ();
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  ref = exrread ([repro_files("measured_pov", c.results, material) ".exr"]);   # the fits' renderer: their PSNR's reference
  fits = jsondecode (fileread (repro_files ("render_fits", c.results, material)));
  [rgb, stops] = img_tonemap (ref, "auto");
  ## the methods' rows, and the published fit's (one lobe) when it was rendered
  rows_ = c.methods;
  lobes = repmat ({c.lobes}, 1, numel (rows_));
  if (isfield (fits, "ngan2005"))
    rows_{end+1} = "ngan2005";
    lobes{end+1} = 1;
  endif
  nm = numel (rows_);
  nk = numel (c.lobes);
  label = struct ("inplane", "in-plane", "hemisphere", "hemisphere", "scene", "scene",
                  "ngan2005", "Ngan 2005");
  names = rows_;
  for i = 1:nm
    if (isfield (label, rows_{i}))
      names{i} = label.(rows_{i});
    endif
  endfor
  ## one panel per image, laid out by hand: image aspect kept, room for a
  ## title: 256 pixels hold "hemisphere 3: 46.3 dB, FLIP 0.833, dE 24.3",
  ## a longer method's name (hemisphere_cooktorrance) widens every panel
  pw = max (256, ceil (5.9 * (max (cellfun (@numel, names)) + 33)));
  ph = round (pw * c.size(1) / c.size(2));
  tt = 36;
  W = pw * (1 + nk);
  H = (ph + tt) * nm;
  h = figure ("visible", "off", "position", [0, 0, W, H]);
  for i = 1:nm
    mth = rows_{i};
    name = names{i};
    y = (nm - i) * (ph + tt) / H;
    for j = 0:numel (lobes{i})
      axes ("position", [j * pw / W + 0.003, y + 0.003, pw / W - 0.006, ph / H - 0.006]);
      if (j == 0)
        show (rgb, "measured");
      else
        img = exrread ([repro_files("fit_render", c.results, material, mth, lobes{i}(j)) ".exr"]);
        r = fits.(mth)(j);
        show (img_tonemap (img, stops), sprintf ("%s %d: %.1f dB, FLIP %.3f, dE %.1f", name, lobes{i}(j),
                                                  num (r, "psnr_pov"), num (r, "flip_pov"),
                                                  num (r, "deltae_pov")), 8, "normal");
      endif
    endfor
  endfor
  file = repro_files ("sheet_png", c.results, material);   # repro_print makes the folder
  repro_print (h, file, 72, "db_sheet");
  R = struct ("file", repro_files ("sheet_png", "", material), "exposure", stops);
endfunction

## the number R.(F), NaN when the record lacks it or holds null (NaN, Inf)
function x = num (r, f)
  x = NaN;
  if (isfield (r, f) && isnumeric (r.(f)) && isscalar (r.(f)))
    x = r.(f);
  endif
endfunction

## RGB in the current axes, titled TTL (fit panels: a smaller, regular
## font, so that PSNR, FLIP and dE fit in the panel's width on one line)
function show (rgb, ttl, fs = 9, fw = "bold")
  image (rgb);
  axis image off;
  set (gca, "xtick", [], "ytick", []);
  title (ttl, "interpreter", "none", "fontsize", fs, "fontweight", fw);
endfunction
