## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{dims}, @var{scale}, @var{n}] =} __lafortune_merl_consts__ ()
## MERL .binary layout constants (private): dims [90 90 180] (theta_h,
## theta_d, phi_d), per-channel scale [1/1500 1.15/1500 1.66/1500], number of
## bins per channel.
## @end deftypefn
function [dims, scale, n] = __lafortune_merl_consts__ ()
  dims = [90 90 180];
  scale = [1/1500, 1.15/1500, 1.66/1500];
  n = prod (dims);
endfunction
