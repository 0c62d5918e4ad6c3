# lit configuration for the generator's golden and diagnostic tests.
import os
import lit.formats

config.name = "dpgen"
config.test_format = lit.formats.ShTest(execute_external=False)
config.suffixes = [".cpp", ".test"]
config.test_source_root = os.path.dirname(__file__)
config.excludes = ["kernels", "modern", "kernels20", "styles", "consumer", "mpi", "adversary", "support", "runtime", "fuzz", "CMakeLists.txt",
                   "lit.cfg.py", "phases_test.cpp", "share_bits_driver.cpp"]
# (phases_test.cpp: doctest; share_bits_driver.cpp: share_same_bits.py's driver; not lit)

tools = config.llvm_tools_dir
config.substitutions.append(("%dpgen", config.dpgen))
config.substitutions.append(("%kernels", config.kernels_dir))
config.substitutions.append(("%runtime_inc", config.runtime_include))
config.substitutions.append(("FileCheck", os.path.join(tools, "FileCheck")))
config.substitutions.append(("%not", os.path.join(tools, "not")))
config.substitutions.append(("%count", os.path.join(tools, "count")))
