/*
 * IPProtocol.h - IPv4 header with byte-order-safe accessors (for raw IP
 * endpoints). Fields are stored in network byte order; the accessors take
 * and return host-order values. Header-only.
 */
#ifndef _IPProtocol_h_DEFINED
#define _IPProtocol_h_DEFINED

#include <antTypes.h>
#include <IPAddress.h>
#include <Internet.h>

struct IPHeader {
    byte   vhl_;    /* version << 4 | header length in 32-bit words */
    byte   tos_;
    uint16 len_;
    uint16 id_;
    uint16 off_;
    byte   ttl_;
    byte   p_;
    uint16 sum_;
    uint32 src_;
    uint32 dst_;

    static uint16 Swap16(uint16 v) { return (uint16)((v >> 8) | (v << 8)); }
    static uint32 Swap32(uint32 v) {
        return (v >> 24) | ((v >> 8) & 0xff00U) | ((v << 8) & 0xff0000U) | (v << 24);
    }

    byte      ip_vGet() const { return (byte)(vhl_ >> 4); }
    void      ip_vSet(byte v) { vhl_ = (byte)((v << 4) | (vhl_ & 0x0f)); }
    byte      ip_hlGet() const { return (byte)(vhl_ & 0x0f); }
    void      ip_hlSet(byte hl) { vhl_ = (byte)((vhl_ & 0xf0) | (hl & 0x0f)); }
    byte      ip_tosGet() const { return tos_; }
    void      ip_tosSet(byte t) { tos_ = t; }
    uint16    ip_lenGet() const { return Swap16(len_); }
    void      ip_lenSet(uint16 l) { len_ = Swap16(l); }
    uint16    ip_idGet() const { return Swap16(id_); }
    void      ip_idSet(uint16 i) { id_ = Swap16(i); }
    uint16    ip_offGet() const { return Swap16(off_); }
    void      ip_offSet(uint16 o) { off_ = Swap16(o); }
    byte      ip_ttlGet() const { return ttl_; }
    void      ip_ttlSet(byte t) { ttl_ = t; }
    Protocol  ip_pGet() const { return p_; }
    void      ip_pSet(Protocol p) { p_ = (byte)p; }
    uint16    ip_sumGet() const { return Swap16(sum_); }
    void      ip_sumSet(uint16 s) { sum_ = Swap16(s); }
    IPAddress ip_srcGet() const { return IPAddress(Swap32(src_)); }
    void      ip_srcSet(IPAddress a) { src_ = Swap32(a.Address()); }
    IPAddress ip_dstGet() const { return IPAddress(Swap32(dst_)); }
    void      ip_dstSet(IPAddress a) { dst_ = Swap32(a.Address()); }
};

#endif /* _IPProtocol_h_DEFINED */
