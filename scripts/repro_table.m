## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{S}, @var{opts}] =} repro_table (@var{b}, @var{name}, @var{c}, @var{max_samples})
## The sample table of the fit method @var{name} of the BRDF @var{b} for
## `make reproduce` and `make database` (configuration @var{c} from
## repro_config), and the options of its fit.  @var{name} is a table,
## optionally with the colour mode of its fit after an underscore
## (@code{scene_shared}, @code{inplane_shared}, @code{scene_separate}) and
## the model it fits (@code{scene_ggx}: the same table; repro_method reads
## the name):
## @code{inplane}, the paper's plane of incidence; @code{hemisphere}, every
## valid bin with its solid-angle weight (at most @var{max_samples}, Inf
## for all); @code{scene}, the angle pairs the scene's pixels see
## (@code{merl_scene} of repro_scene's scene at STUDY_TABLE_SPP samples per
## pixel, with the whole hemisphere as a weak prior).  Grazing angles
## beyond MAX_ANGLE are left out of the first two.  @var{opts}: the
## options of the method's fit for @code{brdf_fit}, @code{@{@}} (its
## defaults for the table: for a scene table the recommended fit, else the
## paper's) or the colour mode.
## @end deftypefn
function [S, opts] = repro_table (b, name, c, max_samples = Inf)
  p = repro_method (name);
  opts = p.opts;
  switch (p.table)
    case "inplane"
      S = merl_plane (b, "max_angle", c.max_angle);
    case "hemisphere"
      S = merl_samples (b, "max_angle", c.max_angle, "max_samples", max_samples);
    case "scene"
      ts = repro_scene (c);
      ts.spp = c.study_table_spp;
      S = merl_scene (b, ts);
    otherwise
      error ("lafortune:badConfig",
             "repro_table: unknown table '%s': expected inplane, hemisphere or scene", p.table);
  endswitch
endfunction
