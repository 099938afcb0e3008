// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __merl_grid__: the directions of MERL bins at their grid points,
// __lafortune_merl_grid__ compiled: a hemisphere table takes about a million
// bins, each eight trigonometric functions and a dozen element-wise Octave
// operations.  __lafortune_merl_grid__.m stays the definition and the
// reference: it calls this through __lafortune_oct_call__, and the tests
// compare the two bit for bit on every bin.  Every operation is the one the
// Octave code makes, in its order (std::sin and std::cos are the C
// library's, as Octave's; x .^ 2 as x * x; built with -ffp-contract=off,
// src/Makefile); the bin's integer coordinates are exact in either.

#include <octave/oct.h>

#include "oct_guard.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>

DEFUN_DLD (__merl_grid__, args, ,
           "-*- texinfo -*-\n\
@deftypefn  {} {[@var{wi}, @var{wo}] =} __merl_grid__ ()\n\
@deftypefnx {} {[@var{wi}, @var{wo}] =} __merl_grid__ (@var{idx})\n\
Internal: the compiled directions of __lafortune_merl_grid__ (see there):\n\
every MERL bin's, or those of the bins with the 1-based indices @var{idx}\n\
(real whole numbers 1 @dots{} 1458000).\n\
@end deftypefn")
{
  const int nargs = args.length ();
  if (nargs > 1)
    print_usage ();
  const bool all = nargs == 0;
  if (! all && (! args(0).is_double_type () || args(0).iscomplex () || args(0).issparse ()))
    error_with_id ("lafortune:badInput", "__merl_grid__: IDX must be real doubles, got %s",
                   what_of (args(0)).c_str ());
  const octave_idx_type n = all ? 1458000 : args(0).numel ();

  Matrix wi (n, 3), wo (n, 3);
  oct_guard ("__merl_grid__", [&] ()
    {
      NDArray idx;
      if (! all)
        idx = args(0).array_value ();
      double *a = wi.fortran_vec ();
      double *b = wo.fortran_vec ();
      for (octave_idx_type i = 0; i < n; i++)
        {
          std::uint64_t k = i;
          if (! all)
            {
              const double x = idx(i);
              if (! (x >= 1 && x <= 1458000 && x == std::floor (x)))
                throw std::invalid_argument ("IDX must hold bin indices 1 ... 1458000");
              k = static_cast<std::uint64_t> (x) - 1;
            }
          const double ip = static_cast<double> (k % 180);
          const double id = static_cast<double> ((k / 180) % 90);
          const double ih = static_cast<double> (k / 16200);
          const double u = ih / 90;
          const double th = u * u * M_PI / 2;       // (ih / 90) .^ 2 * pi / 2
          const double td = id / 90 * M_PI / 2;
          const double pd = ip / 180 * M_PI;
          const double dx = std::sin (td) * std::cos (pd);
          const double dy = std::sin (td) * std::sin (pd);
          const double dz = std::cos (td);
          const double c = std::cos (th);
          const double s = std::sin (th);
          a[i] = dx * c + dz * s;
          a[i + n] = dy;
          a[i + 2 * n] = -dx * s + dz * c;
          b[i] = -dx * c + dz * s;
          b[i + n] = -dy;
          b[i + 2 * n] = dx * s + dz * c;
        }
    });
  return ovl (wi, wo);
}

/*
%!test
%! ## every bin, and a subset in another order: the Octave code's bits
%! ## (__lafortune_merl_grid__'s own test compares it without the oct-file)
%! [wi, wo] = __merl_grid__ ();
%! assert (size (wi), [1458000 3]);
%! idx = [1458000; 1; 16201; 181; 777777];
%! [a, b] = __merl_grid__ (idx);
%! assert (isequal (a, wi(idx,:)) && isequal (b, wo(idx,:)));
%! assert (max (abs (sum (wi .^ 2, 2) - 1)) < 1e-12);
%!error <Invalid call> __merl_grid__ (1, 2)
%!error <IDX must be real doubles> __merl_grid__ (int32 (1))
%!error <IDX must hold bin indices> __merl_grid__ (0)
%!error <IDX must hold bin indices> __merl_grid__ (1.5)
%!error <IDX must hold bin indices> __merl_grid__ (1458001)
*/
