## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{brdf} =} merl_standin (@var{name})
## @deftypefnx {lafortune} {@var{brdf} =} merl_standin (@var{name}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {@var{names} =} merl_standin ()
## A built-in stand-in, in MERL format, for a material of the paper.
##
## The real MERL files are a download; without them the toolbox uses these.
## @var{name} is @code{"green-metallic-paint"} or @code{"red-plastic"}.  The
## material is a Cook-Torrance model (Beckmann distribution, V-groove
## shadowing, Schlick Fresnel) with the parameters Ngan, Durand and Matusik
## (2005) published for the real measurement, sampled on the MERL grid by
## @code{merl_synth}, with measurement-like multiplicative noise (option
## @code{"noise"}, default 0.03) and missing samples beyond 80 degrees
## (option @code{"missing"}, default 80; [] for none).  It looks like the
## real material; it is not the measurement.  The struct's @code{name} says
## @code{"<name> (stand-in)"}.
##
## @example
## @group
## brdf = merl_standin ("red-plastic");
## S = merl_plane (brdf);
## model = lafortune_fit (S, 1);
## @end group
## @end example
## @seealso{merl_synth, merl_read}
## @end deftypefn
function brdf = merl_standin (name, varargin)
  P.green_metallic_paint = struct ("rho_d", [0.00303 0.0415 0.0341],
                                   "rho_s", [0.164 0.165 0.117], "F0", 0.137, "m", 0.143);
  P.red_plastic = struct ("rho_d", [0.271 0.0419 0.00855],
                          "rho_s", [0.193 0.153 0.105], "F0", 0.085, "m", 0.262);
  names = {"green-metallic-paint", "red-plastic"};
  if (nargin == 0)
    brdf = names;
    return;
  endif
  if (! ischar (name) || ! any (strcmp (name, names)))
    error ("lafortune:unknownMaterial",
           "merl_standin: unknown material '%s'; built-in stand-ins: %s",
           __lafortune_arg_str__ (name), strjoin (names, ", "));
  endif
  opt = __lafortune_parse_opts__ (varargin, "merl_standin", struct ("noise", 0.03, "missing", 80, "seed", 1));
  p = P.(strrep (name, "-", "_"));
  m = brdf_model ("cooktorrance", "rho_d", p.rho_d, "ks", p.rho_s, "m", p.m, "F0", p.F0);
  brdf = merl_synth (m, "name", [name " (stand-in)"],
                     "noise", opt.noise, "missing", opt.missing, "seed", opt.seed);
endfunction

%!test
%! assert (merl_standin (), {"green-metallic-paint", "red-plastic"});
%! b = merl_standin ("red-plastic", "noise", 0);
%! assert (b.name, "red-plastic (stand-in)");
%! ## a red diffuse colour: at normal incidence and exit, red > green > blue
%! v = merl_eval (b, [sind(30) 0 cosd(30)], [0 sind(45) cosd(45)]);
%! assert (v(1) > v(2) && v(2) > v(3));
%! ## specular peak at the mirror direction
%! wi = [sind(30) 0 cosd(30)];
%! assert (merl_eval (b, wi, [-wi(1:2) wi(3)])(2) > 4 * v(2));
%! assert (any (! b.valid));

%!error <unknown material 'gold'> merl_standin ("gold")
%!error id=lafortune:unknownMaterial merl_standin (3)
