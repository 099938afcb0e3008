## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} db_sheet (@var{material})
## Gallery step of `make database` (run by repro_step, which writes @var{R}
## to RESULTS/sheet/MATERIAL.json): the material's contact sheet
## RESULTS/sheet/MATERIAL.png, one row per fit method (in-plane: the
## paper's, general: the recommended, scene, hemisphere), the measured data rendered
## by POV-Ray (the reference of the fits' PSNR) first and then the render
## of each lobe count, titled "METHOD K: PSNR, FLIP, dE" (the POV-Ray
## render's PSNR, HDR-FLIP and mean CIEDE2000 against the measured one, as
## in the record of repro_render_fits), all at the measured render's
## exposure; in make database a last row has the published fit
## (repro_render_fits's ngan2005) when it was rendered.  These renders
## are in the light the scene fits were made for: in-sample, which the
## sheet's title says.  With held-out lights (JUDGE), a second sheet
## RESULTS/sheet/MATERIAL-heldout.png shows the same fits rendered by
## rt_render under JUDGE's first light (repro_judge), titled with the
## held-out FLIP, PSNR and dE under that light, its measured render
## titled with the noise floor under that light (repro_judge's
## @code{noise_flip}: the FLIP between two renders of the measured data;
## fits closer than that tie).  @var{R}: @code{file} (the PNG's name,
## relative to RESULTS), @code{exposure} (stops), @code{heldout_file} (""
## without held-out lights), @code{heldout_light} and
## @code{heldout_noise_flip} (NaN without held-out lights).
## @end deftypefn
function R = db_sheet (material)
  c = repro_config ();
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  fits = jsondecode (fileread (repro_files ("render_fits", c.results, material)));
  judge = jsondecode (fileread (repro_files ("judge", c.results, material)));
  ## the fits' renderer's measured render: their PSNR's reference
  ref = exrread ([repro_files("measured_pov", c.results, material) ".exr"]);
  get = @(mth, k) exrread ([repro_files("fit_render", c.results, material, mth, k) ".exr"]);
  stops = sheet (c, fits, ref, get, {"psnr_pov", "flip_pov", "deltae_pov"},
                 sprintf ("%s: in the light the scene fits were made for (in-sample), POV-Ray", material),
                 repro_files ("sheet_png", c.results, material));
  R = struct ("file", repro_files ("sheet_png", "", material), "exposure", stops,
              "heldout_file", "", "heldout_light", "", "heldout_noise_flip", NaN);
  if (! isempty (judge.lights))
    light = judge.lights(1).label;
    ref = exrread ([repro_files("judge_measured", c.results, material) ".exr"]);
    get = @(mth, k) exrread ([repro_files("judge_render", c.results, material, mth, k) ".exr"]);
    R.heldout_noise_flip = num (judge, "noise_flip");
    sheet (c, judge, ref, get, {"psnr", "flip", "deltae"},
           sprintf ("%s: held out, under %s (no fit was made for it), rt_render", material, light),
           repro_files ("sheet_heldout_png", c.results, material),
           sprintf ("measured, noise FLIP %.3f", R.heldout_noise_flip));
    R.heldout_file = repro_files ("sheet_heldout_png", "", material);
    R.heldout_light = light;
  endif
endfunction

## One contact sheet into FILE: the measured render REF first in each row,
## then each method's fits GET (method, k), titled with the record REC's
## measures Q (PSNR, FLIP, dE; the first of a per-light row: the sheet's
## light), the sheet's heading TTL and the measured render's title MTTL;
## returns the exposure (stops)
function stops = sheet (c, rec, ref, get, Q, ttl, file, mttl = "measured")
  [rgb, stops] = img_tonemap (ref, "auto");
  ## the methods' rows, and the published fit's (one lobe) when it was rendered
  rows_ = c.methods;
  lobes = repmat ({c.lobes}, 1, numel (rows_));
  if (isfield (rec, "ngan2005"))
    rows_{end+1} = "ngan2005";
    lobes{end+1} = 1;
  endif
  nm = numel (rows_);
  nk = numel (c.lobes);
  label = struct ("inplane", "in-plane", "hemisphere", "hemisphere", "scene", "scene",
                  "general", "general", "ngan2005", "Ngan 2005");
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
  hh = 30;                               # the sheet's heading
  W = pw * (1 + nk);
  H = (ph + tt) * nm + hh;
  h = figure ("visible", "off", "position", [0, 0, W, H]);
  axes ("position", [0, 1 - hh / H, 1, hh / H], "visible", "off", "xlim", [0 1], "ylim", [0 1]);
  text (0.5, 0.5, ttl, "horizontalalignment", "center", "verticalalignment", "middle", "fontsize", 11,
        "fontweight", "bold", "interpreter", "none");
  for i = 1:nm
    mth = rows_{i};
    name = names{i};
    y = (nm - i) * (ph + tt) / H;
    for j = 0:numel (lobes{i})
      pos = [j * pw / W + 0.003, y + 0.003, pw / W - 0.006, ph / H - 0.006];
      if (j == 0)
        show (pos, rgb, mttl);
      else
        img = get (mth, lobes{i}(j));
        r = rec.(mth)(j);
        show (pos, img_tonemap (img, stops),
              sprintf ("%s %d: %.1f dB, FLIP %.3f, dE %.1f", name, lobes{i}(j),
                       num (r, Q{1}), num (r, Q{2}), num (r, Q{3})), 8, "normal");
      endif
    endfor
  endfor
  repro_print (h, file, 72, "db_sheet");  # makes the folder
endfunction

## the number R.(F) (the first, of a per-light row), NaN when the record
## lacks it or holds null (NaN, Inf)
function x = num (r, f)
  x = NaN;
  if (isfield (r, f) && isnumeric (r.(f)) && ! isempty (r.(f)))
    x = r.(f)(1);
  endif
endfunction

## RGB in new axes at POS (figure units), aspect kept, titled TTL (fit
## panels: a smaller, regular font, so that PSNR, FLIP and dE fit in the
## panel's width on one line).  The axes and the image are made with their
## properties given at once: image () and axis () would reset and restyle
## the axes for every panel.
function show (pos, rgb, ttl, fs = 9, fw = "bold")
  [h, w, ~] = size (rgb);
  cl = [0 1];                            # the colour range of RGB's class
  if (isinteger (rgb))
    cl = double ([intmin(rgb), intmax(rgb)]);
  endif
  ax = axes ("position", pos, "visible", "off", "ydir", "reverse", "clim", cl,
             "xlim", [0.5, w + 0.5], "ylim", [0.5, h + 0.5], "dataaspectratio", [1 1 1]);
  image ("cdata", rgb, "cdatamapping", "direct", "parent", ax);
  title (ax, ttl, "interpreter", "none", "fontsize", fs, "fontweight", fw);
endfunction
