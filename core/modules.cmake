# The core modules in dependency order and what each may use (its direct dependencies; what they
# use comes with them). Read by core/CMakeLists.txt and by tests/core/layering_check.cmake.
set(METROFIT_CORE_MODULES common io optim spc machine geometry setup thermal kinematics matching project
    sim diagnose study)
set(METROFIT_CORE_DEPS_common "")
set(METROFIT_CORE_DEPS_io common)
set(METROFIT_CORE_DEPS_optim common)
set(METROFIT_CORE_DEPS_spc common)
set(METROFIT_CORE_DEPS_machine io)
set(METROFIT_CORE_DEPS_geometry io optim)
set(METROFIT_CORE_DEPS_setup io optim)
set(METROFIT_CORE_DEPS_thermal io optim)
set(METROFIT_CORE_DEPS_kinematics io optim spc)
set(METROFIT_CORE_DEPS_matching io optim machine geometry)
set(METROFIT_CORE_DEPS_project setup thermal kinematics matching machine geometry)
set(METROFIT_CORE_DEPS_sim setup thermal kinematics matching)
set(METROFIT_CORE_DEPS_diagnose project)
set(METROFIT_CORE_DEPS_study diagnose sim)

# Third-party libraries used privately (in .cpp files only).
set(METROFIT_CORE_PRIVATE_common metrofit_glpk)
set(METROFIT_CORE_PRIVATE_io pugixml::pugixml)
set(METROFIT_CORE_PRIVATE_setup metrofit_glpk)
set(METROFIT_CORE_PRIVATE_matching metrofit_glpk)
set(METROFIT_CORE_PRIVATE_geometry metrofit_glpk nanoflann::nanoflann)
set(METROFIT_CORE_PRIVATE_diagnose Boost::headers)
