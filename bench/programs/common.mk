#
# Shared rules of the benchmark objects (Sony's per-object convention, object-model 5.2).
#
OPENRSDK_ROOT?=/usr/local/OPEN_R_SDK
INSTALLDIR=../MS
CXX=$(OPENRSDK_ROOT)/bin/mipsel-linux-g++
STRIP=$(OPENRSDK_ROOT)/bin/mipsel-linux-strip
MKBIN=$(OPENRSDK_ROOT)/OPEN_R/bin/mkbin
STUBGEN=$(OPENRSDK_ROOT)/OPEN_R/bin/stubgen2
MKBINFLAGS=-p $(OPENRSDK_ROOT)
LIBS=-L$(OPENRSDK_ROOT)/OPEN_R/lib -lObjectComm -lOPENR
CXXFLAGS=-O2 -g -I. -I$(OPENRSDK_ROOT)/OPEN_R/include/R4000 -I$(OPENRSDK_ROOT)/OPEN_R/include

%.o: %.cc
	$(CXX) $(CXXFLAGS) -o $@ -c $^
