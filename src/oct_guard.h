// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// oct_guard (WHO, WORK): run an oct-file's WORK (a callable) so that no C++
// exception leaves the oct-file (an oct-file never crashes Octave): running
// out of memory becomes the Octave error lafortune:outOfMemory, any other
// exception lafortune:badInput, with the message "WHO: what went wrong".
// Shared by the compiled inner loops (__merl_nearest__, __rt_traverse__,
// __lafortune_core__, __model_core__, __rt_accum__, __rt_slice__), with
// what_of (V), what an argument is, for their error messages.

#ifndef LAFORTUNE_OCT_GUARD_H
#define LAFORTUNE_OCT_GUARD_H

#include <octave/oct.h>

#include <exception>
#include <new>
#include <string>

template <typename F>
void
oct_guard (const char *who, F work)
{
  std::string err;
  try
    {
      work ();
    }
  catch (const std::bad_alloc&)
    {
      err = "out of memory";
    }
  catch (const std::exception& e)
    {
      err = e.what ();
    }
  catch (...)
    {
      err = "unknown error";
    }
  // raised outside the handlers, so that Octave's own error is not caught
  if (! err.empty ())
    error_with_id (err == "out of memory" ? "lafortune:outOfMemory" : "lafortune:badInput",
                   "%s: %s", who, err.c_str ());
}

// what V is: its size and class, complex or sparse said
inline std::string
what_of (const octave_value& v)
{
  std::string c = v.class_name ();
  if (v.iscomplex ())
    c = "complex " + c;
  if (v.issparse ())
    c = "sparse " + c;
  return v.dims ().str () + " " + c;
}

#endif
