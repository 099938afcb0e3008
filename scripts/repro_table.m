## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{S} =} repro_table (@var{b}, @var{name}, @var{c}, @var{max_samples})
## The sample table of the fit method @var{name} of the BRDF @var{b} for
## `make reproduce` and `make database` (configuration @var{c} from
## repro_config).  @var{name} is a method (repro_method reads it: its
## colour mode and model change the fit, not the table):
## @code{inplane}, the paper's plane of incidence; @code{hemisphere}, every
## valid bin with its solid-angle weight (at most @var{max_samples}, Inf
## for all); @code{general}, the same with merl_samples' training views
## (the table of the general fit, which chooses its weighting by them);
## @code{scene}, the angle pairs the scene's pixels see
## (@code{merl_scene} of repro_scene's scene at STUDY_TABLE_SPP samples per
## pixel, with the whole hemisphere as a weak prior).  Grazing angles
## beyond MAX_ANGLE are left out of the first two.  The fit's options are
## the method's (repro_method's @code{opts}) over brdf_fit's defaults for
## the table (for a scene table the fit for that scene, for the general
## table the general fit, for the in-plane one the paper's).
## @end deftypefn
function S = repro_table (b, name, c, max_samples = Inf)
  p = repro_method (name);
  switch (p.table)
    case "inplane"
      S = merl_plane (b, "max_angle", c.max_angle);
    case "hemisphere"
      S = merl_samples (b, "max_angle", c.max_angle, "max_samples", max_samples, "views", false);
    case "general"
      S = merl_samples (b, "max_angle", c.max_angle, "max_samples", max_samples);
    case "scene"
      ts = repro_scene (c);
      ts.spp = c.study_table_spp;
      S = merl_scene (b, ts);
    otherwise
      error ("lafortune:badConfig",
             "repro_table: unknown table '%s': expected inplane, hemisphere, general or scene", p.table);
  endswitch
endfunction
