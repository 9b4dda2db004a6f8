"""Constants mirrored from ``mortarcontact.h`` (values are frozen by the C ABI; see docs/abi.md).

bindings/python/tests/test_constants.py checks every ``#define``/enum value here against the
header, so a header change that is not mirrored fails the tests.
"""

#: Version of the header these bindings were written against.
MC_VERSION_MAJOR = 0
MC_VERSION_MINOR = 1
MC_VERSION_PATCH = 0
MC_VERSION_NUMBER = MC_VERSION_MAJOR * 10000 + MC_VERSION_MINOR * 100 + MC_VERSION_PATCH
MC_VERSION_STRING = "0.1.0"

# Status codes (mc_status).
MC_OK = 0
MC_ERROR_ARGUMENT = 1
MC_ERROR_MESH = 2
MC_ERROR_MATERIAL = 3
MC_ERROR_STATE = 4
MC_ERROR_CONTACT = 5
MC_ERROR_SINGULAR = 6
MC_ERROR_NOT_CONVERGED = 7
MC_ERROR_MEMORY = 8
MC_ERROR_INTERNAL = 9

# mc_set_plane.
MC_PLANE_STRAIN = 0
MC_PLANE_STRESS = 1

# Component masks for mc_fix.
MC_X = 1
MC_Y = 2
MC_XY = 3

# Options (mc_set_option_int / mc_set_option_real).
MC_OPTION_METHOD = 1
MC_OPTION_TOLERANCE = 2
MC_OPTION_MAX_ITERATIONS = 3
MC_OPTION_ORDERING = 4
MC_OPTION_Q1_INTEGRATION = 6
MC_OPTION_CONTACT_NORMAL = 7
MC_OPTION_THREADS = 10

# Values of MC_OPTION_METHOD.
MC_METHOD_MORTAR = 0
MC_METHOD_DUAL_MORTAR = 1
MC_METHOD_NODE_TO_SEGMENT = 2

# Values of MC_OPTION_CONTACT_NORMAL.
MC_NORMAL_NONMORTAR = 0
MC_NORMAL_MORTAR = 1

# Values of MC_OPTION_ORDERING.
MC_ORDERING_AUTO = 0
MC_ORDERING_AMD = 1
MC_ORDERING_METIS = 2

# Values of MC_OPTION_Q1_INTEGRATION.
MC_Q1_FULL = 0
MC_Q1_BBAR = 1

# Levels of the log callback's messages (mc_log_level).
MC_LOG_PHASE = 1
MC_LOG_ITERATION = 2

# Infos (mc_get_info_int / mc_get_info_real).
MC_INFO_DOFS = 1
MC_INFO_FACTOR_NNZ = 2
MC_INFO_ITERATIONS = 3
MC_INFO_ACTIVE_NODES = 4
MC_INFO_CONTACT_NODES = 5
MC_INFO_FACTORIZATIONS = 6
MC_INFO_TIME_ASSEMBLY = 20
MC_INFO_TIME_ANALYSIS = 21
MC_INFO_TIME_FACTORIZATION = 22
MC_INFO_TIME_SOLVE = 23
MC_INFO_TIME_CONTACT = 24
MC_INFO_TIME_TOTAL = 25
MC_INFO_STRAIN_ENERGY = 26
MC_INFO_COMPLEMENTARITY = 27
MC_INFO_EQUILIBRIUM = 28

#: Options that take an integer value (the others take a real one).
INT_OPTIONS = frozenset({MC_OPTION_METHOD, MC_OPTION_MAX_ITERATIONS, MC_OPTION_ORDERING,
                         MC_OPTION_Q1_INTEGRATION, MC_OPTION_CONTACT_NORMAL, MC_OPTION_THREADS})
#: Infos that are integers (the others are reals).
INT_INFOS = frozenset({MC_INFO_DOFS, MC_INFO_FACTOR_NNZ, MC_INFO_ITERATIONS, MC_INFO_ACTIVE_NODES,
                       MC_INFO_CONTACT_NODES, MC_INFO_FACTORIZATIONS})
