/* The one way both C accelerators hand out their routines: bound(name, python) makes the
   function object of the routine `name` from a module's table, carrying the Python function
   it hands every call its own tests do not settle (the function object's self). */

#ifndef YASEER_BOUND_ROUTINE_H
#define YASEER_BOUND_ROUTINE_H

#include <Python.h>
#include <string.h>

static PyObject *bound_routine(PyMethodDef *routines, PyObject *args)
{
    const char *name;
    PyObject *python;
    if (!PyArg_ParseTuple(args, "sO:bound", &name, &python))
        return NULL;
    if (!PyCallable_Check(python)) {
        PyErr_SetString(PyExc_TypeError, "bound: the Python function must be callable");
        return NULL;
    }
    for (PyMethodDef *def = routines; def->ml_name; def++) {
        if (!strcmp(def->ml_name, name))
            return PyCFunction_NewEx(def, python, NULL);
    }
    PyErr_Format(PyExc_KeyError, "no accelerated routine %s", name);
    return NULL;
}

#endif
