/*
 * OPENR/OFbkImage.h - view of one band of one layer of a filter-bank image
 * (robot-api 6.6). Everything is inline.
 *
 * Rows are band-interleaved: YCrCb layers hold Y,Cr,Cb (stride 3w, Skip 2w),
 * YCrCb_HPF layers hold Y,Cr,Cb,Y_LH,Y_HL,Y_HH (stride 6w, Skip 5w), the CDT
 * layer holds one band (Skip 0). The first 16 bytes of the last row of every
 * band carry a tag (field counter, colour frequencies).
 */
#ifndef _OFbkImage_h_DEFINED
#define _OFbkImage_h_DEFINED

#include <OPENR/ODataFormats.h>

typedef longword OFbkImageBand;
const OFbkImageBand ofbkimageBAND_Y    = 0;   /* Y_LL */
const OFbkImageBand ofbkimageBAND_Cr   = 1;
const OFbkImageBand ofbkimageBAND_Cb   = 2;
const OFbkImageBand ofbkimageBAND_CDT  = 3;
const OFbkImageBand ofbkimageBAND_Y_LH = 4;
const OFbkImageBand ofbkimageBAND_Y_HL = 5;
const OFbkImageBand ofbkimageBAND_Y_HH = 6;

class OFbkImage {
public:
    OFbkImage(OFbkImageInfo* info, byte* data, OFbkImageBand band)
        : width_((int)info->width), height_((int)info->height), skip_(0), image_(0)
    {
        int w = width_;
        int pos = -1;
        if (info->type == odataFBK_YCrCb) {
            skip_ = 2 * w;
            if (band == ofbkimageBAND_Y || band == ofbkimageBAND_Cr ||
                band == ofbkimageBAND_Cb) {
                pos = (int)band;
            }
        } else if (info->type == odataFBK_YCrCb_HPF) {
            skip_ = 5 * w;
            if (band == ofbkimageBAND_Y || band == ofbkimageBAND_Cr ||
                band == ofbkimageBAND_Cb) {
                pos = (int)band;
            } else if (band == ofbkimageBAND_Y_LH || band == ofbkimageBAND_Y_HL ||
                       band == ofbkimageBAND_Y_HH) {
                pos = (int)band - 1;
            }
        } else if (info->type == odataFBK_CDT) {
            skip_ = 0;
            if (band == ofbkimageBAND_CDT) pos = 0;
        }
        if (pos >= 0 && data != 0) image_ = data + pos * w;
    }

    ~OFbkImage() {}

    OFbkImage& operator=(const OFbkImage& o) {
        width_ = o.width_;
        height_ = o.height_;
        skip_ = o.skip_;
        image_ = o.image_;
        return *this;
    }

    bool  IsValid() const { return image_ != 0; }
    byte* Pointer() const { return image_; }
    int   Width() const { return width_; }
    int   Height() const { return height_; }
    int   Skip() const { return skip_; }

    byte Pixel(int x, int y) const {
        return image_[(width_ + skip_) * y + x];
    }

    /* tag in the last row of the band */
    int FieldCounter() const {
        const byte* t = Tag();
        return (int)((word)t[0] | ((word)t[1] << 8));
    }

    int ColorFrequency(OCdtChannel chan) const {
        const byte* t = Tag();
        switch (chan) {
        case ocdtCHANNEL0: return t[8];
        case ocdtCHANNEL1: return t[9];
        case ocdtCHANNEL2: return t[10];
        case ocdtCHANNEL3: return t[11];
        case ocdtCHANNEL4: return t[4];
        case ocdtCHANNEL5: return t[5];
        case ocdtCHANNEL6: return t[6];
        case ocdtCHANNEL7: return t[7];
        default: return 0;
        }
    }

    /* obsolete: 32-bit little-endian word at the start of the tag */
    longword GetTagInfo() const {
        const byte* t = Tag();
        return (longword)t[0] | ((longword)t[1] << 8) |
               ((longword)t[2] << 16) | ((longword)t[3] << 24);
    }

private:
    const byte* Tag() const {
        return image_ + (width_ + skip_) * (height_ - 1);
    }

    int   width_;
    int   height_;
    int   skip_;
    byte* image_;
};

#endif /* _OFbkImage_h_DEFINED */
