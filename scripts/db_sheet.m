## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} db_sheet (@var{material})
## Gallery step of `make database` (run by repro_step, which writes @var{R}
## to RESULTS/sheet/MATERIAL.json): the material's contact sheet
## RESULTS/sheet/MATERIAL.png, one row per fit method (in-plane: the
## paper's, hemisphere, scene: the recommended), the measured data rendered
## by POV-Ray (the reference of the fits' PSNR) first and
## then the render of each lobe count, titled METHOD K: PSNR, all at the
## measured render's exposure.  @var{R}: @code{file} (the PNG's name,
## relative to RESULTS) and @code{exposure} (stops).
## @end deftypefn
function R = db_sheet (material)
  c = repro_config ();
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  rd = fullfile (c.results, "render");
  ref = exrread (fullfile (rd, [material "-measured-pov.exr"]));   # the fits' renderer: their PSNR's reference
  fits = jsondecode (fileread (fullfile (rd, [material "-fits.json"])));
  [rgb, stops] = img_tonemap (ref, "auto");
  nm = numel (c.methods);
  nk = numel (c.lobes);
  label = struct ("inplane", "in-plane", "hemisphere", "hemisphere", "scene", "scene");
  ## one panel per image, laid out by hand: image aspect kept, room for a title
  pw = 220;
  ph = round (pw * c.size(1) / c.size(2));
  tt = 36;
  W = pw * (1 + nk);
  H = (ph + tt) * nm;
  h = figure ("visible", "off", "position", [0, 0, W, H]);
  for i = 1:nm
    mth = c.methods{i};
    name = mth;
    if (isfield (label, mth))
      name = label.(mth);
    endif
    y = (nm - i) * (ph + tt) / H;
    for j = 0:nk
      axes ("position", [j * pw / W + 0.003, y + 0.003, pw / W - 0.006, ph / H - 0.006]);
      if (j == 0)
        show (rgb, "measured");
      else
        img = exrread (fullfile (rd, sprintf ("%s-%s-%d.exr", material, mth, c.lobes(j))));
        show (img_tonemap (img, stops), sprintf ("%s %d: %.2f dB", name, c.lobes(j),
                                                  fits.(mth)(j).psnr_pov));
      endif
    endfor
  endfor
  file = fullfile (c.results, "sheet", [material ".png"]);   # repro_print makes the folder
  repro_print (h, file, 72, "db_sheet");
  R = struct ("file", fullfile ("sheet", [material ".png"]), "exposure", stops);
endfunction

function show (rgb, ttl)
  image (rgb);
  axis image off;
  set (gca, "xtick", [], "ytick", []);
  title (ttl, "interpreter", "none", "fontsize", 9);
endfunction
